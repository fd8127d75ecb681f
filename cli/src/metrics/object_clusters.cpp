#include "object_clusters.hpp"

#include <algorithm>
#include <numeric>

namespace openswarm {

namespace {

// Union-find over object indices.
struct Sets {
    std::vector<size_t> parent;
    explicit Sets(size_t n) : parent(n) { std::iota(parent.begin(), parent.end(), 0); }
    size_t root(size_t i) {
        while (parent[i] != i) i = parent[i] = parent[parent[i]];
        return i;
    }
    void join(size_t a, size_t b) { parent[root(a)] = root(b); }
};

double squared_distance(const ObjectPosition &a, const ObjectPosition &b) {
    double dx = a.x_mm - b.x_mm, dy = a.y_mm - b.y_mm;
    return dx * dx + dy * dy;
}

}  // namespace

double largest_cluster_fraction(const std::vector<ObjectPosition> &objects, double radius_mm) {
    if (objects.empty()) return 0.0;
    double reach = 2 * radius_mm + cluster_gap_mm;
    Sets sets(objects.size());
    for (size_t i = 0; i < objects.size(); i++)
        for (size_t j = i + 1; j < objects.size(); j++)
            if (squared_distance(objects[i], objects[j]) <= reach * reach) sets.join(i, j);
    std::vector<size_t> size(objects.size(), 0);
    for (size_t i = 0; i < objects.size(); i++) size[sets.root(i)]++;
    return (double)*std::max_element(size.begin(), size.end()) / (double)objects.size();
}

double compactness(const std::vector<ObjectPosition> &objects, double radius_mm) {
    if (objects.empty()) return 0.0;
    ObjectPosition centroid{0, 0};
    for (const auto &o : objects) centroid.x_mm += o.x_mm, centroid.y_mm += o.y_mm;
    centroid.x_mm /= (double)objects.size();
    centroid.y_mm /= (double)objects.size();
    double sum = 0;
    for (const auto &o : objects) sum += squared_distance(o, centroid);
    return sum / (4 * radius_mm * radius_mm);
}

}  // namespace openswarm
