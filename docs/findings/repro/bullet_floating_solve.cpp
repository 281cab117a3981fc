// Bullet 3.24's btMultiBody on a floating base: a light base (1/128 kg, moments 1/8) carrying
// a heavy arm (256 kg) on a hinge, in gravity, at one state. Its articulated-body algorithm
// (computeAccelerationsArticulatedBodyAlgorithmMultiDof) solves the base's 6x6 articulated
// inertia with btMultiBody::solveImatrix ("a dedicated 6x6 matrix inverse", btMultiBody.h):
// block formulas with explicit 3x3 inverses. Built twice: as Bullet ships it, and with
// -DLU_SOLVE, where this program replaces solveImatrix by Gaussian elimination with partial
// pivoting of the same cached matrix (read through `private`, the one liberty taken with
// Bullet's headers). Each prints the accelerations and the residuals of Newton's and Euler's
// equations of the whole system and of the hinge, checked on Bullet's own geometry.
#ifdef LU_SOLVE
#define private public
#endif
#include <BulletDynamics/Featherstone/btMultiBody.h>
#ifdef LU_SOLVE
#undef private
#endif
#include <cmath>
#include <cstdio>
#include <utility>

#ifdef LU_SOLVE
// force.angular = BL w + TL^T v, force.linear = TL w + TR v (btSymmetricSpatialDyad's operator*);
// the cached blocks are TopLeft = TL, TopRight = TR, LowerLeft = BL, LowerRight = TL^T.
void btMultiBody::solveImatrix(const btSpatialForceVector& rhs, btSpatialMotionVector& result) const {
  double a[6][7];
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) {
      a[i][j] = m_cachedInertiaLowerLeft[i][j];
      a[i][3 + j] = m_cachedInertiaLowerRight[i][j];
      a[3 + i][j] = m_cachedInertiaTopLeft[i][j];
      a[3 + i][3 + j] = m_cachedInertiaTopRight[i][j];
    }
  for (int i = 0; i < 3; ++i) a[i][6] = rhs.getAngular()[i], a[3 + i][6] = rhs.getLinear()[i];
  for (int c = 0; c < 6; ++c) {
    int p = c;
    for (int r = c + 1; r < 6; ++r)
      if (std::fabs(a[r][c]) > std::fabs(a[p][c])) p = r;
    for (int k = 0; k < 7; ++k) std::swap(a[c][k], a[p][k]);
    for (int r = c + 1; r < 6; ++r) {
      const double f = a[r][c] / a[c][c];
      for (int k = c; k < 7; ++k) a[r][k] -= f * a[c][k];
    }
  }
  double x[6];
  for (int r = 5; r >= 0; --r) {
    double s = a[r][6];
    for (int k = r + 1; k < 6; ++k) s -= a[r][k] * x[k];
    x[r] = s / a[r][r];
  }
  result.setVector(btVector3(x[0], x[1], x[2]), btVector3(x[3], x[4], x[5]));
}
#endif

int main() {
  // The base's frame at its centre of mass on its principal axes (its inertia is isotropic),
  // at the world's origin; the arm's principal axes are its link frame (a diagonal tensor).
  btMultiBody body(1, 1.0 / 128, btVector3(0.125, 0.125, 0.125), false, false);
  btQuaternion origin;  // the hinge's origin rpy (1, -1.25, 2.5): parent to link is its inverse
  origin.setEulerZYX(2.5, -1.25, 1);
  body.setupRevolute(0, 256, btVector3(0.125, 0.5, 0.5), -1, origin.inverse(), btVector3(0, 1, 0),
                     btVector3(0, 0, 0.625), btVector3(-0.0625, 0.09375, -0.375), true);
  body.finalizeMultiDof();
  body.setLinearDamping(0);
  body.setAngularDamping(0);
  body.setJointPos(0, -0.69140625);
  body.setJointVel(0, 1.5);
  body.setBaseOmega(btVector3(-1.921875, 3.484375, 2.97265625));
  body.setBaseVel(btVector3(0.5, -0.25, 1));
  body.addBaseForce(btVector3(0, 0, -9.81 / 128));
  body.addLinkForce(0, btVector3(0, 0, -9.81 * 256));
  body.addBaseTorque(btVector3(0, 0.2890625, 0));
  btAlignedObjectArray<btScalar> r;
  btAlignedObjectArray<btVector3> v;
  btAlignedObjectArray<btMatrix3x3> m;
  body.computeAccelerationsArticulatedBodyAlgorithmMultiDof(0, r, v, m, false, false, false);
  const int n = body.getNumDofs() + 6, out = body.getNumDofs();
  std::printf("accelerations (base omegadot, base vdot at its centre of mass, both in the world; hinge):");
  for (int i = 0; i < n; ++i) std::printf(" %.17g", r[out + i]);
  std::printf("\n");
  // Newton and Euler on Bullet's own geometry, in long double: the base's and the arm's
  // centres of mass, rotations and the hinge's axis as Bullet holds them; their accelerations
  // from the output (the arm's by the hinge's kinematics); the residuals of the total force,
  // the total moment about the world's origin and the hinge's moment on the arm, each relative
  // to the largest term it sums. Exact equations of motion leave rounding only.
  using L = long double;
  struct V {
    L x, y, z;
    V operator+(const V& o) const { return {x + o.x, y + o.y, z + o.z}; }
    V operator-(const V& o) const { return {x - o.x, y - o.y, z - o.z}; }
    V operator*(L s) const { return {x * s, y * s, z * s}; }
    L dot(const V& o) const { return x * o.x + y * o.y + z * o.z; }
    V cross(const V& o) const { return {y * o.z - z * o.y, z * o.x - x * o.z, x * o.y - y * o.x}; }
    L norm() const { return std::sqrt(dot(*this)); }
  };
  const auto in = [](const btVector3& b) { return V{b.x(), b.y(), b.z()}; };
  // I in the world: R diag(moments) R^T, R's columns the body's axes in the world.
  const auto spin = [](const V axes[3], const V& moments, const V& w) {
    const L m[3] = {moments.x, moments.y, moments.z};
    V out{0, 0, 0};
    for (int k = 0; k < 3; ++k) out = out + axes[k] * (m[k] * axes[k].dot(w));
    return out;
  };
  const btQuaternion base_to_world = body.getWorldToBaseRot().inverse();
  V base_axes[3], arm_axes[3];
  for (int k = 0; k < 3; ++k) {
    btVector3 e(0, 0, 0);
    e[k] = 1;
    base_axes[k] = in(quatRotate(base_to_world, e));
    arm_axes[k] = in(body.localDirToWorld(0, e));
  }
  const V moments_base{0.125, 0.125, 0.125}, moments_arm{0.125, 0.5, 0.5};
  const L m_base = 1.0 / 128, m_arm = 256, qd = 1.5, tau_hinge = 0;
  const V gravity{0, 0, -9.81}, torque_base{0, 0.2890625, 0};
  const V x_base = in(body.getBasePos()), x_arm = in(body.localPosToWorld(0, btVector3(0, 0, 0)));
  const V pivot = in(body.localPosToWorld(0, btVector3(0.0625, -0.09375, 0.375)));
  const V axis = in(body.localDirToWorld(0, btVector3(0, 1, 0)));
  const V w_base = in(body.getBaseOmega());
  const V r1 = pivot - x_base, r2 = x_arm - pivot;
  const V w_arm = w_base + axis * qd;
  const V wd_base{r[out], r[out + 1], r[out + 2]}, a_base{r[out + 3], r[out + 4], r[out + 5]};
  const L qdd = r[out + 6];
  const V wd_arm = wd_base + axis * qdd + w_base.cross(axis * qd);
  const V a_arm = a_base + wd_base.cross(r1) + w_base.cross(w_base.cross(r1)) + wd_arm.cross(r2) +
                  w_arm.cross(w_arm.cross(r2));
  const V f_base = a_base * m_base, f_arm = a_arm * m_arm;
  const V force = f_base + f_arm - gravity * (m_base + m_arm);
  const V h_base = spin(base_axes, moments_base, wd_base) + w_base.cross(spin(base_axes, moments_base, w_base));
  const V h_arm = spin(arm_axes, moments_arm, wd_arm) + w_arm.cross(spin(arm_axes, moments_arm, w_arm));
  const V moment = h_base + h_arm + x_base.cross(f_base - gravity * m_base) + x_arm.cross(f_arm - gravity * m_arm) -
                   torque_base;
  const L hinge = axis.dot(h_arm + r2.cross(f_arm - gravity * m_arm)) - tau_hinge;
  const L force_terms = std::fmax((double)f_arm.norm(), (double)(gravity * m_arm).norm());
  const L moment_terms = std::fmax((double)h_arm.norm(), (double)(x_arm.cross(f_arm).norm() + x_arm.norm() * m_arm * 9.81));
  const L hinge_terms = std::fmax((double)h_arm.norm(), (double)(r2.norm() * (f_arm.norm() + m_arm * 9.81)));
  std::printf("Newton-Euler residuals, relative to their terms: force %.3Lg, moment %.3Lg, hinge %.3Lg\n",
              force.norm() / force_terms, moment.norm() / moment_terms, std::fabs(hinge) / hinge_terms);
}
