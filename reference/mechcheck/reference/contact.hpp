#pragma once
/// Rigid bodies in contact with Coulomb friction (one coefficient mu, static = kinetic) and
/// Newton restitution (coefficient e): the motions that have exact answers, in any scalar
/// type, each a piecewise closed form whose events (a stop, the end of slipping, a bounce)
/// are solved exactly. World z is up, gravity g along -z; the ground is the plane z = 0
/// (a slope: the plane turned by alpha about y). What each is a theorem of:
///   - momentum: m dv/dt = sum of the forces (notes eqs 61, 65), the friction -mu N along
///     the slip (Coulomb), so a body sliding flat decelerates at mu g whatever its
///     direction, yaw, mass and size;
///   - angular momentum about the contact point (a point of the ground, eqs 76, 127-129):
///     friction and the normal force act there and gravity through the centre above it, so
///     L_P = I omega + m (x_G - x_P) x v_G is conserved while a ball slides, and its slip
///     decays at the constant rate mu g (1 + m r^2 / I) in a fixed direction;
///   - work and energy: the friction's work mu N d is the kinetic energy lost; rolling
///     without slip dissipates nothing (the contact point is at rest, eq 129's instantaneous
///     axis);
///   - the parallel-axis theorem (eq 160): a body rolling turns about its contact point,
///     with I + m r^2, hence a = g sin(alpha) / (1 + I / (m r^2)).

#include <cmath>
#include <limits>
#include <string>

#include "mechcheck/core.hpp"

namespace mechcheck::reference {

/// A body sliding flat on level ground (a box on a face): from the horizontal velocity v0
/// it decelerates at mu g along -v0 / |v0|, stops at t = |v0| / (mu g) after |v0|^2 /
/// (2 mu g), then rests for ever. Throws domain_error for mu or g not positive, v0 not
/// horizontal (v0_z != 0).
template <class T>
class sliding_on_level {
 public:
  sliding_on_level(const vector3<T>& v0, const T& mu, const T& g) : v0_(v0), mu_(mu), g_(g) {
    require_positive(mu, "sliding_on_level", "friction coefficient mu");
    require_positive(g, "sliding_on_level", "gravity g");
    if (v0(2) != 0) throw domain_error("sliding_on_level: v0 must be horizontal, got v0_z = " + to_text(v0(2)));
  }
  T speed0() const { return v0_.norm(); }
  T deceleration() const { return mu_ * g_; }
  T stop_time() const { return speed0() / deceleration(); }
  T stop_distance() const { return speed0() * speed0() / (2 * deceleration()); }
  /// The displacement from the start at time t >= 0.
  vector3<T> displacement(const T& t) const {
    const T s = speed0();
    if (s == 0) return vector3<T>::Zero();
    const T tt = t < stop_time() ? t : stop_time();
    return vector3<T>(v0_ / s * (s * tt - deceleration() * tt * tt / 2));
  }
  vector3<T> velocity(const T& t) const {
    const T s = speed0();
    if (s == 0 || !(t < stop_time())) return vector3<T>::Zero();
    return vector3<T>(v0_ / s * (s - deceleration() * t));
  }

 private:
  vector3<T> v0_;
  T mu_, g_;
};

/// A body sliding flat along the fall line of a slope of angle alpha (0 <= alpha < pi/2),
/// s the distance down the slope from the start, v0 its rate (positive down the slope). The
/// forces along the slope: g sin(alpha) down it, friction mu g cos(alpha) against the slip;
/// at rest it sticks while tan(alpha) <= mu (the friction cone holds gravity) and slides
/// down at g (sin(alpha) - mu cos(alpha)) otherwise. A body sent up the slope (v0 < 0)
/// decelerates at g (sin + mu cos) until it stops, then sticks or slides down.
template <class T>
class sliding_on_slope {
 public:
  sliding_on_slope(const T& alpha, const T& mu, const T& g, const T& v0 = T(0))
      : alpha_(alpha), mu_(mu), g_(g), v0_(v0) {
    using std::cos;
    using std::sin;
    require_non_negative(mu, "sliding_on_slope", "friction coefficient mu");
    require_positive(g, "sliding_on_slope", "gravity g");
    if (!(alpha >= 0 && alpha < half_pi()))
      throw domain_error("sliding_on_slope: the slope's angle must be in [0, pi/2), got " + to_text(alpha));
    along_ = g * sin(alpha);
    friction_ = mu * g * cos(alpha);
  }
  /// Whether the body at rest stays at rest: tan(alpha) <= mu.
  bool sticks() const { return along_ <= friction_; }
  /// The acceleration down the slope while it slides down (0 where it sticks).
  T down_acceleration() const { return sticks() ? T(0) : T(along_ - friction_); }
  /// When a body sent up the slope stops (0 for v0 >= 0).
  T turn_time() const { return v0_ < 0 ? T(-v0_ / (along_ + friction_)) : T(0); }
  T position(const T& t) const {
    const T t1 = turn_time();
    if (t < t1) return v0_ * t + (along_ + friction_) * t * t / 2;
    const T s1 = v0_ * t1 + (along_ + friction_) * t1 * t1 / 2, dt = t - t1;
    const T start = v0_ < 0 ? T(0) : v0_;
    // Down the slope from t1: at rate `start` (0 after a turn), decelerating where the
    // friction wins (a body sent down a slope it sticks to stops), else accelerating.
    const T a = along_ - friction_;
    if (a < 0 && start > 0) {
      const T stop = start / -a;
      const T d = dt < stop ? dt : stop;
      return s1 + start * d + a * d * d / 2;
    }
    return s1 + start * dt + down_acceleration() * dt * dt / 2;
  }
  T velocity(const T& t) const {
    const T t1 = turn_time();
    if (t < t1) return v0_ + (along_ + friction_) * t;
    const T start = v0_ < 0 ? T(0) : v0_, dt = t - t1, a = along_ - friction_;
    if (a < 0 && start > 0) return dt < start / -a ? T(start + a * dt) : T(0);
    return start + down_acceleration() * dt;
  }

 private:
  static T half_pi() { return boost::math::constants::half_pi<T>(); }
  T alpha_, mu_, g_, v0_, along_, friction_;
};

/// A round body (ball, shell, cylinder: k = I / (m r^2) about its centre) released from
/// rest on a slope of angle alpha: it rolls without slipping while the friction it needs,
/// m g sin(alpha) k / (1 + k), is within mu m g cos(alpha), i.e. mu >= tan(alpha) k / (1 + k)
/// (2/7 tan(alpha) for a solid sphere), and then its centre accelerates at g sin(alpha) /
/// (1 + k) (5/7, 3/5 and 2/3 of g sin(alpha) for a solid sphere, a thin shell and a solid
/// cylinder) with omega r = v throughout; otherwise it slips from the start: the centre at
/// g (sin - mu cos), the spin at mu g cos(alpha) / (k r).
template <class T>
class rolling_on_slope {
 public:
  rolling_on_slope(const T& alpha, const T& mu, const T& g, const T& k, const T& r)
      : alpha_(alpha), mu_(mu), g_(g), k_(k), r_(r) {
    require_non_negative(mu, "rolling_on_slope", "friction coefficient mu");
    require_positive(g, "rolling_on_slope", "gravity g");
    require_positive(k, "rolling_on_slope", "k = I / (m r^2)");
    require_positive(r, "rolling_on_slope", "radius r");
    if (!(alpha > 0 && alpha < boost::math::constants::half_pi<T>()))
      throw domain_error("rolling_on_slope: the slope's angle must be in (0, pi/2), got " + to_text(alpha));
  }
  /// The least friction coefficient for rolling: tan(alpha) k / (1 + k).
  T least_friction() const {
    using std::tan;
    return tan(alpha_) * k_ / (1 + k_);
  }
  bool rolls() const { return mu_ >= least_friction(); }
  /// The centre's acceleration down the slope, and the spin's angular acceleration.
  T acceleration() const {
    using std::cos;
    using std::sin;
    return rolls() ? T(g_ * sin(alpha_) / (1 + k_)) : T(g_ * (sin(alpha_) - mu_ * cos(alpha_)));
  }
  T angular_acceleration() const {
    using std::cos;
    return rolls() ? T(acceleration() / r_) : T(mu_ * g_ * cos(alpha_) / (k_ * r_));
  }
  T distance(const T& t) const { return acceleration() * t * t / 2; }
  T velocity(const T& t) const { return acceleration() * t; }
  T spin(const T& t) const { return angular_acceleration() * t; }

 private:
  T alpha_, mu_, g_, k_, r_;
};

/// A ball (k = I / (m r^2), radius r) on level ground, from its centre's horizontal
/// velocity v0 and angular velocity omega0: its contact point slips at u = v + omega x
/// (-r z), decaying at mu g (1 + 1/k) in a fixed direction until it vanishes at t_roll =
/// |u0| / (mu g (1 + 1/k)); it then rolls for ever at the velocity reached (no rolling
/// resistance). Without spin, t_roll = 2 |v0| / (7 mu g) and the final speed 5/7 |v0| for a
/// solid sphere. The spin about z is kept (a point contact has no pivoting friction).
template <class T>
class billiard {
 public:
  billiard(const vector3<T>& v0, const vector3<T>& omega0, const T& r, const T& k, const T& mu, const T& g)
      : v0_(v0), w0_(omega0), r_(r), k_(k), mu_(mu), g_(g) {
    require_positive(r, "billiard", "radius r");
    require_positive(k, "billiard", "k = I / (m r^2)");
    require_positive(mu, "billiard", "friction coefficient mu");
    require_positive(g, "billiard", "gravity g");
    if (v0(2) != 0) throw domain_error("billiard: v0 must be horizontal, got v0_z = " + to_text(v0(2)));
    const vector3<T> u0 = slip(v0, omega0);
    const T s = u0.norm();
    if (s > 0) direction_ = u0 / s;
    t_roll_ = s / (mu * g * (1 + 1 / k));
  }
  /// The contact point's velocity of a state.
  vector3<T> slip(const vector3<T>& v, const vector3<T>& omega) const {
    return vector3<T>(v + omega.cross(vector3<T>(0, 0, -r_)));
  }
  T roll_time() const { return t_roll_; }
  vector3<T> velocity(const T& t) const {
    const T tt = t < t_roll_ ? t : t_roll_;
    return vector3<T>(v0_ - mu_ * g_ * tt * direction_);
  }
  vector3<T> angular_velocity(const T& t) const {
    const T tt = t < t_roll_ ? t : t_roll_;
    return vector3<T>(w0_ + mu_ * g_ * tt / (k_ * r_) * vector3<T>(vector3<T>::UnitZ().cross(direction_)));
  }
  vector3<T> displacement(const T& t) const {
    const T tt = t < t_roll_ ? t : t_roll_;
    vector3<T> d = v0_ * tt - mu_ * g_ * tt * tt / 2 * direction_;
    if (t > t_roll_) d += velocity(t_roll_) * (t - t_roll_);
    return d;
  }

 private:
  vector3<T> v0_, w0_, direction_ = vector3<T>::Zero();
  T r_, k_, mu_, g_, t_roll_ = 0;
};

/// A ball dropped from rest with its lowest point at height h above level ground,
/// restitution e in [0, 1] (Newton: the normal velocity reverses and is multiplied by e at
/// each contact): it falls for t0 = sqrt(2 h / g), leaves the ground at e^k sqrt(2 g h)
/// after its k-th bounce and rises to e^(2k) h; the bounces end at t = t0 (1 + e) / (1 - e)
/// (a geometric series; at t0 for e = 0), after which it rests. For e = 1 it bounces for
/// ever with period 2 t0.
template <class T>
class bouncing_ball {
 public:
  bouncing_ball(const T& h, const T& e, const T& g) : h_(h), e_(e), g_(g) {
    using std::sqrt;
    require_positive(h, "bouncing_ball", "height h");
    require_positive(g, "bouncing_ball", "gravity g");
    if (!(e >= 0 && e <= 1)) throw domain_error("bouncing_ball: restitution must be in [0, 1], got " + to_text(e));
    t0_ = sqrt(2 * h / g);
  }
  T fall_time() const { return t0_; }
  /// Apex height after bounce k (k = 0: the drop).
  T apex(int k) const {
    using std::pow;
    return h_ * pow(e_, 2 * k);
  }
  /// The k-th bounce's time (k >= 1): t0 (1 + 2 (e + ... + e^(k-1))).
  T bounce_time(int k) const {
    T sum = 0, p = 1;
    for (int j = 1; j < k; ++j) {
      p *= e_;
      sum += p;
    }
    return t0_ * (1 + 2 * sum);
  }
  /// When the bounces end (infinity for e = 1).
  T rest_time() const {
    return e_ < 1 ? T(t0_ * (1 + e_) / (1 - e_)) : T(std::numeric_limits<double>::infinity());
  }
  /// The height of the lowest point at t.
  T height(const T& t) const {
    if (t < t0_) return h_ - g_ * t * t / 2;
    if (!(t < rest_time())) return T(0);
    // The bounce in progress: leave the ground at T_k with speed v_k = e^k sqrt(2 g h).
    using std::sqrt;
    T start = t0_, speed = e_ * sqrt(2 * g_ * h_);
    for (int k = 1; k < 100000; ++k) {
      const T flight = 2 * speed / g_;
      if (t < start + flight || flight == 0) {
        const T dt = t - start;
        return speed * dt - g_ * dt * dt / 2;
      }
      start += flight;
      speed *= e_;
    }
    return T(0);
  }

 private:
  T h_, e_, g_, t0_;
};

/// Two bodies colliding at a contact of normal n (unit, from body 1 towards body 2), without
/// friction, with restitution e in [0, 1]: the impulse J n, J = (1 + e) w / (1/m1 + 1/m2),
/// w = (v1 - v2) . n the approach speed, leaves their tangential velocities and total
/// momentum as they were, reverses the normal relative velocity times e, and takes (1 - e^2)
/// of the relative kinetic energy of the normal motion, (1 - e^2) m1 m2 w^2 / (2 (m1 + m2)).
template <class T>
struct collision_result {
  vector3<T> v1, v2;
  T impulse = 0;      ///< J
  T energy_lost = 0;  ///< (1 - e^2) mu w^2 / 2
};

template <class T>
collision_result<T> collide(const T& m1, const vector3<T>& v1, const T& m2, const vector3<T>& v2, const vector3<T>& n,
                            const T& e) {
  require_positive(m1, "collide", "mass m1");
  require_positive(m2, "collide", "mass m2");
  if (!(e >= 0 && e <= 1)) throw domain_error("collide: restitution must be in [0, 1], got " + to_text(e));
  const T w = (v1 - v2).dot(n);
  collision_result<T> out;
  out.v1 = v1;
  out.v2 = v2;
  if (!(w > 0)) return out;  // separating or resting: no impulse
  const T reduced = m1 * m2 / (m1 + m2);
  out.impulse = (1 + e) * w * reduced;
  out.v1 = v1 - out.impulse / m1 * n;
  out.v2 = v2 + out.impulse / m2 * n;
  out.energy_lost = (1 - e * e) * reduced * w * w / 2;
  return out;
}

}  // namespace mechcheck::reference
