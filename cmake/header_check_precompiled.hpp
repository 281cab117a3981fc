// The third-party headers that mechcheck/core.hpp includes, precompiled once for the header
// check (CMakeLists.txt, MECHCHECK_HEADER_CHECK): parsing them took about 4.5 of each
// header's 5-6 s. A public header that includes core.hpp (or these) gets them anyway, so
// the check still proves that each header includes what it uses of mechcheck's and of
// every other third-party header; what it cannot see is a header that uses these, or the
// standard headers they include (<vector>, <string>, <cmath>, ...), without including
// core.hpp or them. A header that includes none of mechcheck's, Eigen or
// Boost.Multiprecision is compiled without them (CMakeLists.txt).
#include <Eigen/Core>
#include <boost/multiprecision/cpp_bin_float.hpp>
#include <boost/multiprecision/eigen.hpp>
#include <boost/multiprecision/float128.hpp>
#include <boost/multiprecision/mpfr.hpp>
#include <boost/multiprecision/number.hpp>
#include <unsupported/Eigen/AutoDiff>
