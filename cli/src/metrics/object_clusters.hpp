// The object-clustering experiment's metrics (Gauci et al. 2014, as the
// OpenSwarm paper uses them): the proportion of objects in the largest
// cluster, and the compactness of all objects, eq. (2) of the paper.
#pragma once

#include <vector>

namespace openswarm {

struct ObjectPosition {
    double x_mm, y_mm;
};

// Objects whose centres are at most this much farther apart than touching
// are in one cluster: no e-puck (74 mm across) passes between them.
constexpr double cluster_gap_mm = 10.0;

// The largest set of objects linked by neighbours no farther apart than
// 2 radius_mm + cluster_gap_mm, as a fraction of all of them (0 if none).
double largest_cluster_fraction(const std::vector<ObjectPosition> &objects, double radius_mm);

// u = 1 / (4 r^2) x sum over objects of the squared distance to their
// centroid: lower is more compact (the paper's eq. (2)).
double compactness(const std::vector<ObjectPosition> &objects, double radius_mm);

}  // namespace openswarm
