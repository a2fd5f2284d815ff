#pragma once
// The back-to-front order of a k-d tree's bricks from a camera (MWSC section 7): at each split the
// child on the far side of the plane from the eye comes first. The bricks are convex and disjoint,
// so this order is exact for any view, the eye inside a brick included.
#include <vector>

#include "partition/kd_partition.hpp"
#include "view/camera.hpp"

namespace cellproj {

// The leaves under `node` (0: the whole tree), farthest first, as brick numbers.
std::vector<int> back_to_front(const KdTree& tree, const Camera& camera, int node = 0);

// Which child of split node `node` is the far one (drawn first): 0 or 1.
int far_child(const KdNode& node, const Camera& camera);

}  // namespace cellproj
