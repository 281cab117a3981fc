// Orocos KDL alone: TreeFkSolverPos_recursive and TreeJntToJacSolver number a JntArray by the
// joints of their own copy of the tree, which Tree's copy constructor renumbers depth first;
// a tree built breadth first (link1, then its children link2 and link3, then link4 below
// link2) numbers j3 and j4 the other way round. The tree's numbering is GetTreeElementQNr's.
//
// Build: g++ -I/usr/include/eigen3 kdl_tree_copy.cpp -lorocos-kdl -o kdl_tree_copy
// Prints each link's q_nr in the tree and in a copy, then turns j4 alone by 1 rad by the
// tree's numbering: link4's frame should roll by 1 and link3's by 0, and link4's Jacobian
// column of j4 should be the x axis.
#include <cstdio>

#include <kdl/jacobian.hpp>
#include <kdl/tree.hpp>
#include <kdl/treefksolverpos_recursive.hpp>
#include <kdl/treejnttojacsolver.hpp>

int main() {
  using namespace KDL;
  Tree tree("base");
  const Frame up(Vector(0, 0, 1));
  const RigidBodyInertia body(1, Vector::Zero(), RotationalInertia(1, 1, 1));
  tree.addSegment(Segment("link1", Joint("j1", Joint::RotZ), up, body), "base");
  tree.addSegment(Segment("link2", Joint("j2", Joint::RotX), up, body), "link1");
  tree.addSegment(Segment("link3", Joint("j3", Joint::RotX), up, body), "link1");
  tree.addSegment(Segment("link4", Joint("j4", Joint::RotX), up, body), "link2");
  const Tree copy(tree);
  for (const char* s : {"link1", "link2", "link3", "link4"})
    std::printf("%s q_nr tree %u copy %u\n", s, GetTreeElementQNr(tree.getSegment(s)->second),
                GetTreeElementQNr(copy.getSegment(s)->second));
  const unsigned j4 = GetTreeElementQNr(tree.getSegment("link4")->second);
  JntArray q(tree.getNrOfJoints());
  q(j4) = 1.0;
  TreeFkSolverPos_recursive fk(tree);
  for (const char* s : {"link3", "link4"}) {
    Frame f;
    const int status = fk.JntToCart(q, f, s);
    double roll, pitch, yaw;
    f.M.GetRPY(roll, pitch, yaw);
    std::printf("JntToCart %s status %d roll %.17g (want %g)\n", s, status, roll, s[4] == '4' ? 1.0 : 0.0);
  }
  TreeJntToJacSolver solver(tree);
  Jacobian jac(tree.getNrOfJoints());
  const int status = solver.JntToJac(q, jac, "link4");
  std::printf("JntToJac link4 status %d column %u (j4) angular %g %g %g (want 1 0 0)\n", status, j4, jac(3, j4),
              jac(4, j4), jac(5, j4));
  return 0;
}
