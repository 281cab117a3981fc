/* ODE's dWorldQuickStep solves a hinge's constraint by a fixed number of SOR iterations
 * (dWorldSetQuickStepNumIterations: "More iterations will give a more accurate solution";
 * "The default is 20 iterations"): what one step leaves unconverged, against the iteration
 * count and against dWorldStep. Uses ODE only.
 *
 * Problem: a pendulum, bob 1 kg with central inertia 1e-3 at 1 m from a hinge about world
 * y at the origin, g = 9.81 along -z, released at rest at theta0 = 0.1 (the centre of mass
 * at (-sin 0.1, 0, -cos 0.1), the body turned by 0.1 about y); one step of h = 0.01. Printed: the anchor's distance from
 * the pivot (the point of the body at the hinge, pos - R (0, 0, -1)), and the angular
 * velocity about y relative to dWorldStep's.
 *
 * Build: cc ode_quickstep_hinge.c $(pkg-config --cflags --libs ode) -lm
 * Prints: lines "name value" (see ci/findings). */
#include <math.h>
#include <stdio.h>

#include <ode/ode.h>

struct outcome {
  double anchor, omega_y;
};

static struct outcome one_step(int quick, int iterations) {
  dRandSetSeed(0); /* QuickStep orders its rows with ODE's random generator */
  dWorldID world = dWorldCreate();
  dWorldSetGravity(world, 0, 0, -9.81);
  if (iterations > 0) dWorldSetQuickStepNumIterations(world, iterations);
  dBodyID body = dBodyCreate(world);
  dMass mass;
  dMassSetParameters(&mass, 1, 0, 0, 0, 1e-3, 1e-3, 1e-3, 0, 0, 0);
  dBodySetMass(body, &mass);
  const double theta = 0.1;
  dMatrix3 r;
  dRFromAxisAndAngle(r, 0, 1, 0, theta);
  dBodySetRotation(body, r);
  dBodySetPosition(body, -sin(theta), 0, -cos(theta)); /* R (0, 0, -1) */
  dJointID hinge = dJointCreateHinge(world, NULL);
  dJointAttach(hinge, body, NULL);
  dJointSetHingeAnchor(hinge, 0, 0, 0);
  dJointSetHingeAxis(hinge, 0, 1, 0);
  if (quick)
    dWorldQuickStep(world, 0.01);
  else
    dWorldStep(world, 0.01);
  const dReal* p = dBodyGetPosition(body);
  const dReal* R = dBodyGetRotation(body); /* 3 rows of 4 */
  /* The body's point at the hinge: pos + R (0, 0, 1) (the pivot is 1 m above the bob). */
  const double ax = p[0] + R[2], ay = p[1] + R[6], az = p[2] + R[10];
  struct outcome o = {sqrt(ax * ax + ay * ay + az * az), dBodyGetAngularVel(body)[1]};
  dWorldDestroy(world);
  return o;
}

int main(void) {
  dInitODE2(0);
  const struct outcome step = one_step(0, 0);
  printf("dworldstep_anchor_after_one_step %.3e\n", step.anchor);
  const int counts[] = {20, 40, 80, 160};
  for (int i = 0; i < 4; ++i) {
    const struct outcome q = one_step(1, counts[i]);
    printf("quickstep_%d_anchor_after_one_step %.3e\n", counts[i], q.anchor);
    printf("quickstep_%d_omega_over_dworldstep %.4f\n", counts[i], q.omega_y / step.omega_y);
  }
  dCloseODE();
  return 0;
}
