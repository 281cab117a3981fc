# ctest starts the longest tests first when it knows their cost, and a fresh clone's build
# does not (build/Testing/Temporary/CTestCostData.txt is written by a run): without it the
# 39 s command test could start last and hold one core while the other idles. The tests of
# 5 s or more, each with its seconds from that file after a run of ci/test (commit 729be34).
# CMakeLists.txt gives the costs to the tests it adds and writes those of the tests
# discovered at test time into a file ctest reads after discovering them; a name this build
# lacks (a client whose runtime is absent, a law left out) is ignored.
set(MECHCHECK_TEST_COSTS
    cli.command:39
    exec.scipy.RK23:23
    exec.node.mujoco_dynamics:18
    exec.sympy_dynamics:18
    exec.scipy.Radau:18
    noether.broken_symmetry.mpfr50:10
    Model.LagrangianModelPosesTheSameProblemAsItsHamiltonian:7
    exec.node.mujoco:7
    exec.scipy.BDF:6
    EngineRobots.AnEngineOfTheRightModelIsOfOrderFourAndTheWrongModelIsContradictedUnlessItSaysWhichItHolds:6
    user_dynamics.a_templated_library_is_judged_in_every_tier:5)
