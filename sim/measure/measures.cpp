#include "sim/measure/measures.h"

#include "sim/stepped/broad_phase.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace carom {

int restingCount(const std::vector<BallState>& state) {
  return static_cast<int>(
      std::count_if(state.begin(), state.end(), [](const BallState& s) { return s.resting; }));
}

OverlapReport measureOverlaps(const Bodies& bodies, const std::vector<Vec3>& positions) {
  OverlapReport report;
  for (int i = 0; i < static_cast<int>(positions.size()); ++i) {
    const Vec3& p = positions[i];
    const double r = bodies.radius[i];
    bool escaped = false;
    for (const PlaneShape& plane : bodies.planes) {
      const double gap = plane.gap(p, r);
      report.maxPenetration = std::max(report.maxPenetration, -gap);
      escaped = escaped || gap + r < 0.0;
    }
    for (const CylinderShape& cylinder : bodies.cylinders) {
      const double gap = cylinder.contact(p, r).gap;
      report.maxPenetration = std::max(report.maxPenetration, -gap);
      escaped = escaped || gap + r < 0.0;
    }
    for (const BoxShape& box : bodies.boxes) {
      const double gap = box.contact(p, r).gap;
      report.maxPenetration = std::max(report.maxPenetration, -gap);
      escaped = escaped || gap + r < 0.0;
    }
    if (escaped) ++report.escaped;
  }
  forEachCloseBallPair(positions, bodies.radius, 0.0, [&](int i, int j) {
    const double overlap =
        bodies.radius[i] + bodies.radius[j] - (positions[i] - positions[j]).norm();
    report.maxPenetration = std::max(report.maxPenetration, overlap);
  });
  return report;
}

double distributionDistance(std::vector<double> a, std::vector<double> b) {
  if (a.empty() || b.empty()) return a.empty() && b.empty() ? 0.0 : 1.0;
  // A run gone wrong may hold NaN, which sorting cannot order: it counts as the largest value.
  for (std::vector<double>* sample : {&a, &b}) {
    for (double& value : *sample)
      if (std::isnan(value)) value = std::numeric_limits<double>::infinity();
    std::sort(sample->begin(), sample->end());
  }
  // Walk both in order; at each value, step past every copy of it in both before comparing, so
  // ties between the samples add no gap.
  const double na = static_cast<double>(a.size()), nb = static_cast<double>(b.size());
  std::size_t i = 0, j = 0;
  double largest = 0.0;
  while (i < a.size() && j < b.size()) {
    const double value = std::min(a[i], b[j]);
    while (i < a.size() && a[i] == value) ++i;
    while (j < b.size() && b[j] == value) ++j;
    largest =
        std::max(largest, std::abs(static_cast<double>(i) / na - static_cast<double>(j) / nb));
  }
  return largest;
}

}  // namespace carom
