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
  // The exact test: no sliver of back face leaks past a silhouette.
  // Density thinning follows; both are filters, and sample_visible oversamples so that
  // options.points survive them.
  const auto keep = [&](const PointList& points) {
    const PointList seen = options.view ? visible_on_solids(points, objects, *options.view) : points;
    return thin_by_density(seen, options.density, rng);
  };
  cloud.points = options.view || options.density.active()
                     ? sample_visible(sample, keep, options.points, rng)
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
  cloud.info.density_falloff_from = options.density.falloff_from;
  cloud.info.patchiness = options.density.patchiness;
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
    const auto vector_at = [&document](const char* key) {
      const auto& v = document.at(key);
      return Eigen::Vector3d(v.at(0).get<double>(), v.at(1).get<double>(), v.at(2).get<double>());
    };
    if (document.contains("view")) options.view = vector_at("view");
    if (document.contains("density_falloff_from"))
      options.density.falloff_from = vector_at("density_falloff_from");
    options.density.patchiness = document.value("patchiness", 0.0);
    return make_synthetic_cloud(objects, options, document.at("seed").get<std::uint64_t>());
  } catch (const nlohmann::json::exception& e) {
    throw std::invalid_argument(std::string("ground truth: ") + e.what());
  }
}

}  // namespace cloudshape::synth
