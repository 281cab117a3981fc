#pragma once
/// Jointed bodies with no closed form: a planar chain of links hinged about world y, the
/// four-bar linkage (a chain closed on the ground), and N bodies under their mutual
/// gravitation. Each is a Hamiltonian templated on its scalar (the tier, AD, mpfr50), so
/// that model.hpp certifies its reference; the engines' multibody scenarios
/// (engines.hpp) are measured against them.
///
/// Planar chain. Link k's frame is turned by its absolute angle phi_k about world y
/// (R(phi) takes +z towards +x); its hinge is the frame's origin: link 0's at `origin` in
/// the world, link k's at hinge_k in link k-1's frame. Its centre of mass is at com_k in its
/// frame, its moment about y through the centre of mass is I_k, gravity g is along -z:
///   c_k = origin + sum_{i<k} R(phi_i) hinge_{i+1} + R(phi_k) com_k,
///   dc_k/dphi_i = e_y x R(phi_i) a_ik,  a_ik = hinge_{i+1} (i < k), com_k (i = k),
///   M_ij = sum_k m_k dc_k/dphi_i . dc_k/dphi_j + delta_ij I_i,
///   H = p^T M(phi)^-1 p / 2 + sum_k m_k g (c_k)_z      (notes eqs 245-255: the Legendre
/// transform of T = phidot^T M phidot / 2 - V, with p = M phidot).
/// Only the x and z components of the offsets enter: the links are symmetric about the
/// plane of motion (no offset along y, principal axes along the world's at phi = 0).
///
/// Four-bar. A crank of length a turns about the world origin (absolute angle phi_1, the
/// one degree of freedom), a coupler of length b joins its tip A to B, a rocker of length c
/// joins B to the ground point D = (d, 0, 0). Each bar is uniform (centre of mass at its
/// middle, moment I about it) and lies along its frame's x axis, u(phi) = R(phi) e_x =
/// (cos phi, 0, -sin phi). B is where the circles |B - A| = b and |B - D| = c meet, on the
/// side `branch` of A -> D; with Grashof's s + l < p + q and the crank the shortest bar, B
/// exists for every phi_1 and the linkage has one smooth configuration manifold. Velocities
/// are linear in phidot_1: from (B - A).(Bdot - Adot) = 0 and (B - D).Bdot = 0, so
///   H = p_1^2 / (2 m(phi_1)) + V(phi_1),  m = sum_k (m_k |dc_k/dphi_1|^2 + I_k (dphi_k/dphi_1)^2).
///
/// N bodies. H = sum |p_i|^2 / 2 m_i - sum_{i<j} G m_i m_j / |q_i - q_j| in three dimensions.

#include <cmath>
#include <string>
#include <vector>

#include "mechcheck/core.hpp"

namespace mechcheck::audit {

namespace detail {
/// R(phi) v in the (x, z) plane: (x cos + z sin, -x sin + z cos).
template <class S>
void turn(const S& c, const S& s, const S& x, const S& z, S& out_x, S& out_z) {
  out_x = x * c + z * s;
  out_z = z * c - x * s;
}
}  // namespace detail

/// One link of a planar chain (see the header): parameters in double, read exactly in
/// every tier.
struct planar_link {
  double mass = 1;
  double moment = 1;            ///< about y through the centre of mass
  double com_x = 0, com_z = 0;  ///< centre of mass in the link's frame
  double hinge_x = 0, hinge_z = 0;  ///< its hinge in the parent's frame (link 0: the world's)
};

struct planar_chain {
  std::vector<planar_link> links;
  double gravity = 0;

  /// Centres of mass (x, z) and their derivatives in phi: jac[k](i) = d(c_k)/dphi_i.
  template <class S>
  void centres(const dynamic_vector<S>& phi, std::vector<S>& cx, std::vector<S>& cz,
               std::vector<dynamic_vector<S>>& jx, std::vector<dynamic_vector<S>>& jz) const {
    using R = real_type_t<S>;
    using std::cos;
    using std::sin;
    const Eigen::Index n = static_cast<Eigen::Index>(links.size());
    if (phi.size() != n)
      throw dimension_error("planar_chain: " + std::to_string(n) + " links but " + std::to_string(phi.size()) +
                            " angles");
    const auto c = [](double v) { return lift<S>(R(v)); };
    cx.assign(std::size_t(n), c(0));
    cz = cx;
    jx.assign(std::size_t(n), dynamic_vector<S>::Constant(n, c(0)));
    jz = jx;
    S hx = c(links[0].hinge_x), hz = c(links[0].hinge_z);  // link k's hinge in the world
    for (Eigen::Index k = 0; k < n; ++k) {
      const planar_link& l = links[std::size_t(k)];
      const S co = cos(phi(k)), si = sin(phi(k));
      S ax, az;
      detail::turn(co, si, c(l.com_x), c(l.com_z), ax, az);
      cx[std::size_t(k)] = hx + ax;
      cz[std::size_t(k)] = hz + az;
      // e_y x w = (w_z, 0, -w_x): this link's own turn, then every earlier link's.
      jx[std::size_t(k)](k) = az;
      jz[std::size_t(k)](k) = -ax;
      if (k + 1 < n) {
        const planar_link& next = links[std::size_t(k + 1)];
        S bx, bz;
        detail::turn(co, si, c(next.hinge_x), c(next.hinge_z), bx, bz);
        for (Eigen::Index j = k + 1; j < n; ++j) {
          jx[std::size_t(j)](k) = bz;
          jz[std::size_t(j)](k) = -bx;
        }
        hx += bx;
        hz += bz;
      }
    }
  }

  /// The mass matrix M(phi) of T = phidot^T M phidot / 2.
  template <class S>
  dynamic_matrix<S> mass_matrix(const dynamic_vector<S>& phi) const {
    using R = real_type_t<S>;
    std::vector<S> cx, cz;
    std::vector<dynamic_vector<S>> jx, jz;
    centres(phi, cx, cz, jx, jz);
    const Eigen::Index n = phi.size();
    dynamic_matrix<S> m = dynamic_matrix<S>::Constant(n, n, lift<S>(R(0)));
    for (Eigen::Index k = 0; k < n; ++k) {
      const S mk = lift<S>(R(links[std::size_t(k)].mass));
      for (Eigen::Index i = 0; i <= k; ++i)
        for (Eigen::Index j = 0; j <= i; ++j) {
          const S e = mk * (jx[std::size_t(k)](i) * jx[std::size_t(k)](j) + jz[std::size_t(k)](i) * jz[std::size_t(k)](j));
          m(i, j) += e;
        }
      m(k, k) += lift<S>(R(links[std::size_t(k)].moment));
    }
    for (Eigen::Index i = 0; i < n; ++i)
      for (Eigen::Index j = i + 1; j < n; ++j) m(i, j) = m(j, i);
    return m;
  }

  template <class S>
  S potential(const dynamic_vector<S>& phi) const {
    using R = real_type_t<S>;
    std::vector<S> cx, cz;
    std::vector<dynamic_vector<S>> jx, jz;
    centres(phi, cx, cz, jx, jz);
    S v = lift<S>(R(0));
    for (std::size_t k = 0; k < links.size(); ++k) v += lift<S>(R(links[k].mass * gravity)) * cz[k];
    return v;
  }

  template <class S>
  S operator()(const dynamic_vector<S>& q, const dynamic_vector<S>& p) const {
    // p^T M^-1 p (M is positive definite for positive masses and moments).
    using R = real_type_t<S>;
    const S kinetic = inverse_quadratic_form(mass_matrix(q), p, "planar_chain");
    return kinetic / lift<S>(R(2)) + potential(q);
  }
};

/// The four-bar linkage (see the header): bar lengths, masses, moments about their centres.
struct four_bar {
  double crank = 1, coupler = 2, rocker = 1.5, ground = 2;
  double mass[3] = {1, 1, 1};
  double moment[3] = {1, 1, 1};
  double gravity = 0;
  int branch = 1;  ///< +1: B on the left of A -> D (towards +z when A -> D points along +x)

  /// The configuration at crank angle phi1 and its rates per unit phidot1: the joints A, B
  /// (x, z), the absolute angles phi_k and dphi_k/dphi1, the centres' velocities per unit.
  template <class S>
  struct configuration {
    S ax, az, bx, bz;
    S phi[3], rate[3];
    S cx[3], cz[3], vx[3], vz[3];
  };

  template <class S>
  configuration<S> at(const S& phi1) const {
    using R = real_type_t<S>;
    using std::atan2;
    using std::cos;
    using std::sin;
    using std::sqrt;
    const auto c = [](double v) { return lift<S>(R(v)); };
    configuration<S> g;
    const S co = cos(phi1), si = sin(phi1);
    g.ax = c(crank) * co;
    g.az = -c(crank) * si;
    const S adx = c(ground) - g.ax, adz = -g.az;  // A -> D
    const S dist2 = adx * adx + adz * adz, dist = sqrt(dist2);
    const S along = (c(coupler * coupler) - c(rocker * rocker) + dist2) / (c(2) * dist);
    const S across2 = c(coupler * coupler) - along * along;
    if (!(innermost_value(across2) > 0))
      throw domain_error("four_bar: the coupler and the rocker do not meet at crank angle " +
                         to_text(innermost_value(phi1)));
    const S across = c(double(branch)) * sqrt(across2);
    // The left normal of A -> D in (x, z): (-adz, adx) / dist.
    g.bx = g.ax + (along * adx - across * adz) / dist;
    g.bz = g.az + (along * adz + across * adx) / dist;
    // Absolute angles: u(phi) = (cos phi, -sin phi) in (x, z).
    g.phi[0] = phi1;
    g.phi[1] = atan2(-(g.bz - g.az), g.bx - g.ax);
    g.phi[2] = atan2(g.bz, c(ground) - g.bx);
    // Per unit phidot1: Adot = a u'(phi1), u' = (-sin, -cos); Bdot from
    // (B - A).(Bdot - Adot) = 0, (B - D).Bdot = 0 by Cramer's rule.
    const S dax = -c(crank) * si, daz = -c(crank) * co;
    const S e1x = g.bx - g.ax, e1z = g.bz - g.az, e2x = g.bx - c(ground), e2z = g.bz;
    const S rhs = e1x * dax + e1z * daz, det = e1x * e2z - e1z * e2x;
    const S dbx = rhs * e2z / det, dbz = -rhs * e2x / det;
    // dphi/dt = (e x edot)_y / |e|^2, (a x b)_y = a_z b_x - a_x b_z.
    g.rate[0] = c(1);
    g.rate[1] = (e1z * (dbx - dax) - e1x * (dbz - daz)) / c(coupler * coupler);
    const S e3x = c(ground) - g.bx, e3z = -g.bz;  // B -> D, its derivative -Bdot
    g.rate[2] = (e3z * (-dbx) - e3x * (-dbz)) / c(rocker * rocker);
    const S half = c(0.5);
    g.cx[0] = half * g.ax, g.cz[0] = half * g.az, g.vx[0] = half * dax, g.vz[0] = half * daz;
    g.cx[1] = half * (g.ax + g.bx), g.cz[1] = half * (g.az + g.bz);
    g.vx[1] = half * (dax + dbx), g.vz[1] = half * (daz + dbz);
    g.cx[2] = half * (g.bx + c(ground)), g.cz[2] = half * g.bz, g.vx[2] = half * dbx, g.vz[2] = half * dbz;
    return g;
  }

  template <class S>
  S operator()(const dynamic_vector<S>& q, const dynamic_vector<S>& p) const {
    using R = real_type_t<S>;
    const configuration<S> g = at(q(0));
    S m = lift<S>(R(0)), v = lift<S>(R(0));
    for (int k = 0; k < 3; ++k) {
      m += lift<S>(R(mass[k])) * (g.vx[k] * g.vx[k] + g.vz[k] * g.vz[k]) + lift<S>(R(moment[k])) * g.rate[k] * g.rate[k];
      v += lift<S>(R(mass[k] * gravity)) * g.cz[k];
    }
    return p(0) * p(0) / (lift<S>(R(2)) * m) + v;
  }
};

/// N bodies in three dimensions under their mutual gravitation G.
struct n_bodies {
  std::vector<double> masses;
  double gravitation = 1;

  template <class S>
  S operator()(const dynamic_vector<S>& q, const dynamic_vector<S>& p) const {
    using R = real_type_t<S>;
    using std::sqrt;
    S h = lift<S>(R(0));
    const std::size_t n = masses.size();
    for (std::size_t i = 0; i < n; ++i)
      for (int c = 0; c < 3; ++c) {
        const S pc = p(Eigen::Index(3 * i) + c);
        h += pc * pc / lift<S>(R(2 * masses[i]));
      }
    for (std::size_t i = 0; i < n; ++i)
      for (std::size_t j = i + 1; j < n; ++j) {
        S r2 = lift<S>(R(0));
        for (int c = 0; c < 3; ++c) {
          const S d = q(Eigen::Index(3 * i) + c) - q(Eigen::Index(3 * j) + c);
          r2 += d * d;
        }
        h -= lift<S>(R(gravitation * masses[i] * masses[j])) / sqrt(r2);
      }
    return h;
  }
};

}  // namespace mechcheck::audit
