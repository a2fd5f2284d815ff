#include "partition/brick_order.hpp"

namespace cellproj {

int far_child(const KdNode& n, const Camera& camera) {
  // Orthographic: every ray runs along the view direction, so the child it reaches last is the far
  // one. Perspective: the child on the other side of the plane from the eye (the eye on the plane
  // sees each side through the plane never: either order is right).
  if (camera.projection == Projection::Orthographic) return (camera.target - camera.eye)[n.axis] > 0 ? 1 : 0;
  return camera.eye[n.axis] <= n.plane ? 1 : 0;
}

std::vector<int> back_to_front(const KdTree& tree, const Camera& camera, int node) {
  std::vector<int> order, stack{node};
  while (!stack.empty()) {
    const KdNode& n = tree.nodes[stack.back()];
    stack.pop_back();
    if (n.leaf()) {
      order.push_back(n.brick);
      continue;
    }
    const int far = far_child(n, camera);
    stack.push_back(n.children[1 - far]);  // popped after the far child's whole subtree
    stack.push_back(n.children[far]);
  }
  return order;
}

}  // namespace cellproj
