// The tunables of each pipeline stage as plain structs with their defaults. Lengths
// are multiples of the cloud resolution (mean nearest-neighbour distance) or fractions
// of the object's size, so every unit and scale works the same.
#pragma once

#include <cstdint>

namespace cloudshape::config {

// What a cloud may cost before anything is done with it: the readers (cloudshape-recognize,
// cloudshape-inject) and ingest refuse bigger input with an error naming the limit.
struct InputConfig {
  std::int64_t max_points = 5'000'000;      // points of one cloud, counting non-finite ones
  std::int64_t max_bytes = 1'000'000'000;   // bytes of one file, of one raw cloud's coordinates (24 per point) or of a PointCloud2's data
  // Larger coordinates are no measurement in any unit, and sums of their squares or centroids
  // of them overflow to infinity (found by fuzzing): such a cloud is refused.
  double max_coordinate = 1e30;
};

// How the recognition runs, not what it finds: the answers are the same for any value.
struct ExecutionConfig {
  std::int64_t threads = 0;  // threads of the recognition, the caller's included; 0 = one per core
  // The services keep up to this much freed memory for the next cloud instead of returning it
  // to the system, which would fault every page of a frame's buffers in again (0: the C library's own).
  std::int64_t retained_memory_mb = 512;
};

struct PreprocessConfig {
  double voxel_divisions = 200.0;       // voxel edge = bounding-box diagonal / this
  std::int64_t max_points = 12000;      // the voxel grows until at most this many remain
  // Radius outlier filter at the voxel's scale: a voxel with fewer occupied neighbours
  // (of 26) is dropped. 0 disables it.
  std::int64_t isolated_voxel_neighbours = 2;
  // Statistical outlier removal (k-NN mean distance beyond mean + stddev * sigma); slower,
  // for clouds with clustered outliers.
  bool statistical_outliers = false;
  std::int64_t outlier_neighbours = 8;
  double outlier_stddev = 3.0;
  // Edge-preserving smoothing: flat neighbourhoods projected on their local plane. Off by
  // default because the voxel centroids already average the sensor noise of every voxel.
  bool smoothing = false;
  std::int64_t smoothing_neighbours = 16;
  double smoothing_max_curvature = 0.01;  // only neighbourhoods flatter than this are smoothed
  double noise_resolution = 3.0;  // a depth image's pixels noisy on their own: an object's resolution at least this many times its points' noise (0: off)
  double free_space_reach = 3.0;  // a lidar object carries the frame's returns within this many
                                  // times its own angular radius (solve.free_space_max_share)
};

struct PlanesConfig {
  double coarse_threshold = 3.0;        // first RANSAC pass, in resolutions (thesis: two thresholds)
  double fine_threshold = 0.8;          // refit pass, in resolutions
  double noise_sigmas = 2.5;            // ... in a depth camera's view at least this many times the noise along its rays (up to coarse)
  double face_max_sagitta = 0.6;        // a patch bending less than this (x fine threshold) is a face...
  double face_min_radius_ratio = 5.0;   // ... and so is one curving over a radius this many times its width (a bulging real face)
  double min_plane_fraction = 0.015;    // smallest plane, as a fraction of the cloud's points
  std::int64_t min_plane_points = 20;
  std::int64_t max_planes = 16;
  std::int64_t max_rejected_in_row = 6;  // stop after this many non-face planes in a row
  std::int64_t ransac_iterations = 60;   // hypotheses per plane
  std::int64_t score_samples = 1500;     // points that score a hypothesis before the full count
  double sample_radius = 8.0;            // hypothesis triples drawn within this many resolutions
  double connectivity = 2.5;             // inliers farther than this (resolutions) from the main patch are dropped
  std::int64_t boundary_neighbours = 12;
  double boundary_gap_degrees = 150.0;   // in-plane angular gap that makes a point a boundary point
  double line_distance = 2.0;            // boundary points within this (resolutions) support a line
  std::int64_t line_min_support = 4;     // support points each plane must give a line
  double min_line_angle_degrees = 15.0;  // planes closer to parallel than this make no line
  std::uint64_t seed = 42;               // RANSAC is deterministic for a given seed
};

struct KeypointsConfig {
  std::int64_t neighbourhood = 96;      // points per key-point neighbourhood (thesis 3.2.2 used 16; on voxelised clouds 96 types corners far more reliably)
  std::int64_t pursuit_max_steps = 200;
  double merge_distance = 3.0;          // key-points closer than this (resolutions) are one
};

struct ClassifyConfig {
  std::int64_t min_points = 30;          // fewer usable points: the cloud holds no solid
  double border_curvature = 0.02;        // surface variation below this: border (thesis 3.2.2)
  double corner_gap_degrees = 210.0;     // projected angular gap above this: corner (thesis 3.2.3)
  double inner_exclusion = 0.7;          // neighbours nearer than this share of the farthest are ignored in the gap
  std::int64_t apex_candidates = 1;      // the key-point's nearest samples also tried as the wedge's tip
  double sphere_max_rms = 0.02;          // sphere test: fit RMS / radius below this
  double sphere_max_face_fraction = 0.3; // ... and at most this fraction of points on true faces
  double polyhedron_face_fraction = 0.85;  // faces covering this fraction: a polyhedron
  double degenerate_thickness = 0.5;     // spread (std dev, resolutions) below which the cloud is flat or a line
  double outline_min_share = 0.1;        // faces holding this share of the points have their outline read (circle or rectangle)
  double outline_circle_rms = 0.08;      // outline RMS off its circle (share of the radius) at most this: a circle
  double outline_circle_harmonic = 0.04; // ... and no 3rd-8th angular harmonic of it above this share of the radius (a polygon's corners)
  double outline_rect_fill = 0.89;       // hull filling this share of its enclosing rectangle: a rectangle (a disc fills pi/4)
};

// Scene segmentation (common/segment): the cloud as a graph of nodes (pixels of an organized
// cloud, voxels otherwise), structure planes out, smooth patches joined across convex junctions.
struct SegmentConfig {
  std::int64_t target_nodes = 40000;       // organized: the graph has about this many nodes (pixel stride chosen for it)
  std::int64_t voxel_target_nodes = 20000; // unorganized: a surface occupying more cells than this is gridded coarser, to about this many
  std::int64_t isolated_target_nodes = 5000; // unorganized, not a lidar frame: gridded to about this many nodes first, and segmented there when no plane reaches structure_reach beyond what stands on it and one object leaves out fewer than min_object_nodes points (0: off)
  double depth_jump = 0.02;                // organized: neighbours whose ranges differ by more than this share of the range are not connected
  std::int64_t normal_radius = 2;          // organized: half-width of a node's normal window, in nodes
  double crease_degrees = 25.0;            // organized: normals normal_radius nodes away either side turning concavely by more than this: a crease ...
  double crease_flank_share = 0.33;        // ... whose flanks a further normal_radius out turn by less than this share of it
  std::int64_t normal_neighbours = 16;     // unorganized: nodes in a node's normal neighbourhood
  double line_spread = 0.1;                // unorganized: a neighbourhood spreading less than this across (share of along) is one scan line ...
  std::int64_t line_max_neighbours = 128;  // ... and grows up to this many nodes until it spans a surface (lidar rings)
  double scan_elevation_bin_degrees = 0.05;  // unorganized: elevations from the origin binned this finely ...
  double scan_beam_share = 0.9;            // ... and this share of the points in ...
  double scan_beam_bins = 3.0;             // ... beams (runs of occupied bins, empty ones between, 10 points or more) no wider than this on average: a lidar frame with its sensor at the origin (the viewpoint)
  double smooth_degrees = 10.0;            // neighbouring nodes with normals within this angle grow one smooth patch
  double edge_curvature = 0.04;            // ... over surface nodes: a node curved more than this (surface variation) lies on an edge
  double convex_tolerance_degrees = 15.0;  // a junction whose normals differ by less than this is convex whatever its sign
  double convex_share = 0.5;               // adjacent patches join when at least this share of their junction is convex
  double crease_overlap = 0.5;             // ... and, meeting at an angle, their spans along the crease overlap by this share of the shorter (0: off)
  double crease_band = 4.0;                // ... (each patch's nodes within this many node spacings of the other's plane)
  double piece_band = 3.0;                 // a patch of flat pieces (node spacings off a plane) ...
  std::int64_t piece_max_planes = 3;       // ... two to this many (0 or 1: off) ...
  double piece_cover = 0.9;                // ... holding this share of it is split into them
  double flat_junction_length = 0.5;       // organized: two parallel patches side by side join only along at least this many times the square root of the smaller one's nodes
  double concave_cut_band = 3.0;           // organized: a segment whose flat patch meets another of its patches concavely is cut along its plane: within this many node spacings of it is on it ...
  // ... a patch with more than this share of its surface nodes beyond the band on one side goes
  // there; on both, a flat one (a face through the cut) or one not two flat pieces stops it ...
  double concave_cut_cross_share = 0.05;
  // ... unless it spreads off its plane this many times as far as its two pieces off theirs (two
  // solids' faces meeting at a kink; 0: a flat one always stops it)
  double concave_cut_kink_ratio = 2.0;
  double cavity_concavity = 0.3;           // a segment this concave towards the sensor (mean n . (x - c) over its RMS spread) is a container's inside: it joins the container ...
  double cavity_gap = 10.0;                 // ... the segment with the most nodes within this many node spacings of it
  std::int64_t structure_max_planes = 8;   // structure planes (table, floor, walls) removed at most
  double structure_min_share = 0.03;       // a structure plane holds at least this share of the nodes ...
  double structure_band = 3.0;             // ... within this many node spacings of it, normals within structure_normal_degrees
  double structure_normal_degrees = 25.0;
  double structure_reach = 4.0;            // ... and covers at least this many times the area of what stands on it (a solid's face covers about its own solid)
  double structure_contact = 3.0;          // ... and what stands on it touches it (nodes within this many bands above it) ...
  std::int64_t structure_margin_cells = 3; // ... inside it: structure_min_standing of those have plane this many cells (2 node spacings) beyond them on all four sides
  double structure_contact_min_degrees = 12.0;  // ... where it meets the plane (down its own slope): none for surfaces closer to parallel than this
  std::int64_t structure_min_standing = 10;  // nodes that must stand on the viewer's side of a plane for it to be structure
  double structure_max_behind = 0.25;      // ... and, after the first support, the surface joined to it reaches behind it at most this share of its narrower extent (a solid's face has its solid behind it)
  double structure_enclosing = 0.75;       // in a lidar frame (scan_beam_*), a plane with this share of the other nodes on the viewer's side ...
  double structure_span = 0.3;             // ... spanning this share of the scene (standard deviations along the largest axis) is structure too: a wall or ground seen from inside
  std::int64_t structure_hypotheses = 200; // RANSAC hypotheses per structure plane
  double contact_noise_sigmas = 3.0;       // an object's points within this many of a structure plane's own noise deviations of it, over its footprint, are the plane's (the cells at the object's foot hold both; unorganized: finer-graph nodes, about each cell's own height) ...
  double contact_min_band = 0.1;           // ... the band at least this many of its node spacings (a noise-free plane has no noise of its own)
  double camera_facing_share = 0.25;       // unorganized: a scene seen from the origin is a camera's view only where at least this share of what the structure leaves faces the origin (outward normals)
  double remainder_refine = 2.0;           // unorganized: what structure leaves is re-gridded when the node budget alone would make its voxel at least this many times finer
  double fragment_max_width = 2.0;         // a segment this narrow (spread across its length, node spacings) ...
  double fragment_min_elongation = 3.0;    // (depth image: strips this long or bordering one) ...
  double fragment_max_share = 0.2;         // ... and smaller than this share of the largest is a sliver a sensor leaves along silhouettes
  std::int64_t min_object_nodes = 30;      // segments with fewer nodes are clutter (lidar: after a try alone)
  std::int64_t scan_object_min_beams = 2;  // in a lidar frame (scan_beam_*), an object on fewer beams is a strip of ground or wall: one ring shows no vertical extent (two fix a sphere)
  double scan_leftover_share = 0.5;         // ... and one with this share of its points within structure_band (its own point spacings) of a structure plane is a leftover of it
  double min_object_share = 0.002;         // ... and so are those with less than this share of the nodes
  std::int64_t seed = 7;                   // RANSAC seed: the same cloud always gives the same segments
};

struct SolveConfig {
  double inlier_distance = 2.0;          // points within this (resolutions) of the solid explain it
  double min_inlier_fraction = 0.5;      // below this no candidate solid is reported
  double parallel_degrees = 10.0;        // normals within this angle count as parallel
  double perpendicular_degrees = 10.0;   // ... or as perpendicular
  double apex_conditioning = 0.0001;     // tangent planes meeting less decisively than this (eigenvalue ratio) have no apex: a singular system
  double cap_band = 3.0;                 // side fits of cylinders and cones skip points this near (resolutions) a cap plane
  double face_slab = 0.03;               // box faces: median of the points this share of the extent from each end
  double open_end_quantile = 0.9;       // box end without a face: this quantile of the slab (even spread)
  double cap_circle_agreement = 0.1;     // the side's own circle is kept when centre and radius lie within this share of the cap circle's radius of it
  double min_side_share = 0.05;          // a cylinder with a circular cap takes its radius from the side when this share of the points is on it
  double side_fit_min_inlier_fraction = 0.7;  // the cylinder from side normals alone (the second chance) is reported only if it explains this share
  double second_chance_round_below =
      0.9;  // ... tried also where a sphere or cylinder chosen explains less than this share (0:
            // only where no candidate explains min_inlier_fraction)
  double min_side_arc_degrees = 90.0;    // ... and only if its side's explained points cover this arc around the axis
  double cylinder_refine_band = 6.0;     // a cylinder axis from side normals is refined on side points within this (resolutions) of its side ...
  std::int64_t cylinder_refine_iterations = 15;  // ... in at most this many Gauss-Newton steps (0: the normals' axis as it is)
  std::int64_t frustum_side_samples = 4000;  // a frustum from its side alone is refined on at most this many points, evenly strided (0: all)
  double inside_view_share = 0.5;        // a sphere, cone or frustum whose surface mostly (this share of the points) faces away from the sensor is seen from its hollow side: a container
  double container_rim_quantile = 0.995;  // ... whose envelope cylinder reaches this quantile of the points' distances from its axis and along it
  double rim_distance = 3.0;             // points this far (resolutions) beyond a cylinder cap are a rim: height includes it
  double max_size_ratio = 1.5;           // no dimension may exceed this times the cloud's enclosing diameter
  double sector_min_share = 0.02;        // a direction sector with fewer points than this share of an even split is unseen: partial
  std::int64_t verify_samples = 4000;    // points the verification of a candidate solid looks at
  double flat_noise_sigmas = 2.5;        // in a depth camera's view, the plane a round solid is weighed against takes this many noise deviations along the rays
  double preferred_margin = 0.02;        // solids explaining within this share of the best are all in the running...
  double closer_fit_margin = 0.25;       // ... and one with an RMS this much lower than the key-point class's wins
  double ambiguity_rms_ratio = 1.0;      // ... another family's as close (this x its RMS): unknown
  double guessed_side_cost = 0.02;       // ... less this per prism side on its cap's border alone
  double min_side_span = 0.8;            // a prism side seen spans at least this share of the fitted side's width (+ inlier_distance at each edge)
  double polyhedron_face_share = 0.5;    // tetrahedron and prism fits: planes along their faces hold at least this share of the points (prism sides: of the points of planes around the axis)
  std::int64_t extent_hull_samples = 2000;  // points the extent's minimum-area rectangles are chosen from (its bounds take every point)
  std::int64_t solid_min_scan_lines = 5;  // a lidar object on fewer scan lines is tried as a sphere only ...
  double scan_noise_ratio = 3.0;         // ... and its solid leaves the points at most this many times their noise from it (0: off)
  double free_space_max_share = 0.05;    // ... and is unknown where more than this share of the rays crossing it return from beyond it (0: off)
  double off_surface_max_share = 0.08;   // an object seen whole and alone is unknown where more than this share of its points lie on a surface inside its solid (0: off) ...
  double off_surface_distance = 1.5;     // ... farther than this many inlier_distance inside it
  double apex_gap = 0.1;                 // a cone whose points stop this share of its slant height short of the apex, ringing its axis there, was cut: no cone
  double cone_tip_gap = 0.2;             // ... and no cone either when its points stop this share short of the apex, ringing it or not (a frustum seen from one side)
  double frustum_min_taper = 0.2;        // a frustum's radii differ by at least this share of the larger (less: a cylinder's)
  double frustum_min_top_share = 0.1;    // ... and its smaller radius is at least this share of the larger (less: a cone's apex)
  double frustum_side_fill = 0.8;        // a frustum from its side alone: this share of ten stretches of its height hold side points
  double regular_tolerance = 0.03;       // a tetrahedron is regular when each of its six edges lies within this share of their mean
  double triangle_fill_tolerance = 0.15; // a face seen as a tetrahedron's triangle: its points' hull within this share of the triangle's area
  double flat_face_fill_cells = 2.0;     // cell of the fill test below, in resolutions
  double flat_face_min_fill = 0.5;       // a flat face off the caps counts only when its points cover this share of its convex hull (a scan line does not)
  double arc_max_scatter_cells = 0.5;    // ... nor when they lie within this many fill cells (rms) of one circular arc ...
  double arc_min_sagitta_cells = 2.0;    // ... bowing at least this many fill cells off its chord: a scan ring on a round surface
  double curved_side_flat_share = 0.6;   // at most this share of a cylinder's, sphere's, cone's or frustum's points off its caps on true flat faces (an octahedron: nearly all) ...
  double side_face_min_share = 0.1;      // ... a cone's or frustum's faces counting only when each holds this share of the points (apex strips are small)
  // a cylinder is claimed only when at least this share of its points lie on its side: a flat
  // face within a cap's circle (a tetrahedron's, two boxes' tops) has almost none
  double cylinder_min_side_share = 0.05;
  // a cone or frustum is claimed only when its points reach this share of its base radius from
  // its axis: its rim is where its side ends, not beyond the points (0: off)
  double tapered_min_rim_reach = 0.9;
  double box_face_rect_fill = 0.6;       // a box's larger faces fill at least this share of their smallest enclosing rectangle (a triangle: half) ...
  double box_outline_min_share = 0.15;   // ... those holding at least this share of the flat faces' points
  double box_depth_min_share = 0.05;    // a box seen on one face alone needs this share of the points off it
  double stray_face_degrees = 20.0;      // a face farther than this from every face direction of a box or tetrahedron is none of its faces ...
  double stray_face_share = 0.25;     // at most this share of the faces' points on faces along none of a box's or tetrahedron's face directions (an octahedron's: a quarter or more)
  double box_slanted_width_ratio = 0.5;  // a face along none of a box's axes sharing an edge with a face along one, the narrower of the two at least this share of the wider's width across it, rules the box out ...
  double box_edge_distance = 3.0;        // ... sharing an edge: both have points within this (resolutions) of their planes' line, over a common stretch
  double box_step_min_share = 0.1;       // a face along one of a box's axes (within parallel_degrees) holding this share of the flat faces' points ...
  double box_step_depth = 0.1;           // ... with face points beyond its plane on both sides, farther than this share of the points' extent along its normal ...
  double box_step_share = 0.05;          // ... more than this share of the face points on each side, is a step (an L's inner face): no box
  double prism_side_fill = 0.6;          // the convex hull of a prism side's points covers at least this share of its rectangle (an octahedron's triangles: half)
  double cap_section_fill = 0.8;         // a seen cap of a pentagonal prism: the convex hull of the points on its plane covers at least this share of the pentagon (a rhombus at a pentagon's angle: 0.58)
  double prism_run_gap = 4.0;            // a prism side face's points split where they leave a gap this wide (resolutions): coplanar sides of a non-convex outline
  double prism_corner_gap = 8.0;         // two prism sides meet at a corner when one's points end this near (resolutions) where the next's begin
  double prism_outline_cell = 2.0;       // a cap's outline (a prism seen from one side) is traced on cells this wide (resolutions)
  double prism_min_turn_degrees = 20.0;  // a prism's outline turns at least this much at every corner: shallower is a curved side cut into strips
  double prism_notch_outside_share = 0.02;  // an object alone in its cloud (no viewpoint) whose cap outline has a concave corner no side face shows: at most this share of its points outside that outline
  double prism_notch_min_share = 0.1;    // ... and the notches take at least this share of the outline's convex hull (less is a dented border)
  double prism_corner_cut_cells = 3.0;   // a cap-outline side no face shows, shorter than this (outline cells): a rounded corner, its neighbours meet
  double prism_border_band_cells = 2.0;  // cap border points this near the outline (outline cells) place its sides
  double prism_join_evidence = 2.0;      // neighbouring unseen cap-outline sides are one unless two lines fit their border better by this many variances per log
  double prism_guessed_slack = 2.0;      // with a side only the cap's border shows, a pentagon regular within this multiple of the tolerances is pentagonal_prism's
};

}  // namespace cloudshape::config
