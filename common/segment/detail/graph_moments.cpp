#include "segment/detail/graph_moments.hpp"

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cmath>

namespace cloudshape::segment::detail {

void normal_of(const Moments& m, Eigen::Vector3d& normal, double& curvature, double* spread) {
  if (spread) *spread = 1.0;
  if (m.count < 3) {
    normal = Eigen::Vector3d::UnitZ();
    curvature = 1.0 / 3.0;
    return;
  }
  Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eig;
  eig.computeDirect(m.covariance());
  normal = eig.eigenvectors().col(0).normalized();
  const double total = eig.eigenvalues().sum();
  curvature = total > 0.0 ? std::max(0.0, eig.eigenvalues()(0)) / total : 0.0;
  if (spread) {
    const double major = eig.eigenvalues()(2);
    *spread = major > 0.0 ? std::sqrt(std::max(0.0, eig.eigenvalues()(1)) / major) : 0.0;
  }
}

namespace {

// True only when the spread (middle over largest eigenvalue, square-rooted) is surely at least
// `line`, from the trace and the principal minors alone: with eigenvalues l0 <= l1 <= l2 (l0 at
// worst a rounding below 0), e2 = l0 l1 + l0 l2 + l1 l2 <= 3 l1 l2 and l2 <= trace, so
// l1 / l2 >= e2 / (3 trace^2). Asking twice line^2 of that bound leaves the solver's rounding
// (far below a factor of two on l1 / l2 this large) no say: a surface's neighbourhood skips
// the eigenvalues.
bool spreads_across(const Eigen::Matrix3d& c, double line) {
  const double trace = c(0, 0) + c(1, 1) + c(2, 2);
  const double e2 = c(0, 0) * c(1, 1) - c(0, 1) * c(0, 1) + c(0, 0) * c(2, 2) - c(0, 2) * c(0, 2) +
                    c(1, 1) * c(2, 2) - c(1, 2) * c(1, 2);
  return trace > 0.0 && e2 >= 6.0 * line * line * trace * trace;
}

}  // namespace

bool along_a_line(const Moments& m, double line, Eigen::Vector3d& direction) {
  if (m.count < 3) return false;
  const Eigen::Matrix3d cov = m.covariance();
  if (spreads_across(cov, line)) return false;
  Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eig;
  eig.computeDirect(cov, Eigen::EigenvaluesOnly);
  const double major = eig.eigenvalues()(2);
  const double spread = major > 0.0 ? std::sqrt(std::max(0.0, eig.eigenvalues()(1)) / major) : 0.0;
  if (spread >= line) return false;
  eig.computeDirect(cov);
  direction = eig.eigenvectors().col(2).normalized();
  return true;
}

void fill_spacing(NeighbourGraph& g, double fallback, parallel::ThreadPool* pool) {
  g.spacing.assign(g.size(), fallback);
  parallel::for_blocks(pool, g.size(), kNodesPerBlock, [&](std::size_t begin, std::size_t end) {
    for (auto n = static_cast<std::uint32_t>(begin); n < end; ++n) {
      double sum = 0.0;
      int count = 0;
      g.for_neighbours(n, [&](std::uint32_t m) {
        sum += (g.nodes[n] - g.nodes[m]).norm();
        ++count;
      });
      if (count > 0) g.spacing[n] = sum / count;
    }
  });
}

}  // namespace cloudshape::segment::detail
