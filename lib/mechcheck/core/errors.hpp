#pragma once
/// Typed errors thrown at the API boundary. Every message starts with the name of the
/// function that refused the input and names the offending value.

#include <stdexcept>
#include <string>

namespace mechcheck {

/// Base of every error mechcheck throws on bad input.
class error : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

/// A value that must be finite is NaN or infinite.
class non_finite_error : public error {
 public:
  using error::error;
};

/// Sizes that must agree do not (degrees of freedom, vector lengths).
class dimension_error : public error {
 public:
  using error::error;
};

/// A parameter outside its physical domain (non-positive mass, ...).
class domain_error : public error {
 public:
  using error::error;
};

/// A matrix that must be invertible is singular to the tier's precision
/// (e.g. the kinetic matrix d2L/dqdot2 of a degenerate Lagrangian).
class singular_error : public error {
 public:
  using error::error;
};

/// An iteration (Newton, an implicit step) did not converge to the tier's precision.
class convergence_error : public error {
 public:
  using error::error;
};

}  // namespace mechcheck
