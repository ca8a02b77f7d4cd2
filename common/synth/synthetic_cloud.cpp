#include "synth/synthetic_cloud.hpp"
#include "synth/perturb.hpp"
#include "synth/sample_solid.hpp"
#include "synth/solid_visibility.hpp"
#include "synth/visibility.hpp"

#include <random>
#include <stdexcept>

namespace cloudshape::synth {

namespace {

// Area-proportional multinomial split of n points, so each object is as dense as the others.
PointList sample_objects(const std::vector<SolidSpec>& objects, const std::vector<double>& areas,
                         double total_area, std::size_t n, std::mt19937_64& rng) {
  PointList points;
  points.reserve(n);
  std::size_t left = n;
  double area_left = total_area;
  for (std::size_t i = 0; i < objects.size(); ++i) {
    std::size_t count = left;
    if (i + 1 < objects.size()) {
      std::binomial_distribution<std::size_t> share(left, std::min(1.0, areas[i] / area_left));
      count = share(rng);
    }
    const PointList part = sample_solid_surface(objects[i], count, rng);
    points.insert(points.end(), part.begin(), part.end());
    left -= count;
    area_left -= areas[i];
  }
  return points;
}

}  // namespace

SyntheticCloud make_synthetic_cloud(const std::vector<SolidSpec>& objects,
                                    const CloudOptions& options, std::uint64_t seed) {
  if (objects.empty()) throw std::invalid_argument("no objects to sample");
  std::mt19937_64 rng(seed);
  std::vector<double> areas;
  double total_area = 0.0;
  for (const auto& spec : objects) total_area += areas.emplace_back(surface_area(spec));

  SyntheticCloud cloud;
  cloud.objects = objects;
  const auto sample = [&](std::size_t m) {
    return sample_objects(objects, areas, total_area, m, rng);
  };
  // The exact test, not the z-buffer: no sliver of back face leaks past a silhouette.
  const auto keep_visible = [&](const PointList& points) {
    return visible_on_solids(points, objects, *options.view);
  };
  cloud.points = options.view
                     ? sample_visible(sample, keep_visible, options.points, rng)
                     : sample(options.points);
  add_gaussian_noise(cloud.points, options.noise_sigma, rng);
  const std::size_t clean = cloud.points.size();
  add_outliers(cloud.points, options.outlier_fraction, rng);

  cloud.info.points = cloud.points.size();
  cloud.info.seed = seed;
  cloud.info.noise_sigma = options.noise_sigma;
  cloud.info.outlier_fraction = options.outlier_fraction;
  cloud.info.outliers = cloud.points.size() - clean;
  cloud.info.view = options.view;
  return cloud;
}

SyntheticCloud regenerate_from_ground_truth(const nlohmann::json& document) {
  const std::vector<SolidSpec> objects = solids_from_ground_truth(document);
  try {
    CloudOptions options;
    options.points =
        document.at("points").get<std::size_t>() - document.at("outliers").get<std::size_t>();
    options.noise_sigma = document.at("noise_sigma").get<double>();
    options.outlier_fraction = document.at("outlier_fraction").get<double>();
    if (document.contains("view")) {
      const auto& v = document.at("view");
      options.view =
          Eigen::Vector3d(v.at(0).get<double>(), v.at(1).get<double>(), v.at(2).get<double>());
    }
    return make_synthetic_cloud(objects, options, document.at("seed").get<std::uint64_t>());
  } catch (const nlohmann::json::exception& e) {
    throw std::invalid_argument(std::string("ground truth: ") + e.what());
  }
}

}  // namespace cloudshape::synth
