// The name of every field of every stage config, visited in declaration order, so
// the YAML loader and the tests walk one list instead of repeating it.
#pragma once

#include "config/pipeline_config.hpp"

namespace cloudshape::config {

template <class F>
void visit_fields(InputConfig& c, F&& f) {
  f("max_points", c.max_points);
  f("max_bytes", c.max_bytes);
  f("max_coordinate", c.max_coordinate);
}

template <class F>
void visit_fields(ExecutionConfig& c, F&& f) {
  f("threads", c.threads);
  f("retained_memory_mb", c.retained_memory_mb);
}

template <class F>
void visit_fields(PreprocessConfig& c, F&& f) {
  f("voxel_divisions", c.voxel_divisions);
  f("max_points", c.max_points);
  f("isolated_voxel_neighbours", c.isolated_voxel_neighbours);
  f("statistical_outliers", c.statistical_outliers);
  f("outlier_neighbours", c.outlier_neighbours);
  f("outlier_stddev", c.outlier_stddev);
  f("smoothing", c.smoothing);
  f("smoothing_neighbours", c.smoothing_neighbours);
  f("smoothing_max_curvature", c.smoothing_max_curvature);
  f("noise_resolution", c.noise_resolution);
  f("free_space_reach", c.free_space_reach);
}

template <class F>
void visit_fields(SegmentConfig& c, F&& f) {
  f("target_nodes", c.target_nodes);
  f("voxel_target_nodes", c.voxel_target_nodes);
  f("isolated_target_nodes", c.isolated_target_nodes);
  f("depth_jump", c.depth_jump);
  f("normal_radius", c.normal_radius);
  f("crease_degrees", c.crease_degrees);
  f("crease_flank_share", c.crease_flank_share);
  f("normal_neighbours", c.normal_neighbours);
  f("line_spread", c.line_spread);
  f("line_max_neighbours", c.line_max_neighbours);
  f("scan_elevation_bin_degrees", c.scan_elevation_bin_degrees);
  f("scan_beam_share", c.scan_beam_share);
  f("scan_beam_bins", c.scan_beam_bins);
  f("smooth_degrees", c.smooth_degrees);
  f("edge_curvature", c.edge_curvature);
  f("convex_tolerance_degrees", c.convex_tolerance_degrees);
  f("convex_share", c.convex_share);
  f("crease_overlap", c.crease_overlap);
  f("crease_band", c.crease_band);
  f("piece_band", c.piece_band);
  f("piece_max_planes", c.piece_max_planes);
  f("piece_cover", c.piece_cover);
  f("flat_junction_length", c.flat_junction_length);
  f("concave_cut_band", c.concave_cut_band);
  f("concave_cut_cross_share", c.concave_cut_cross_share);
  f("concave_cut_kink_ratio", c.concave_cut_kink_ratio);
  f("cavity_concavity", c.cavity_concavity);
  f("cavity_gap", c.cavity_gap);
  f("structure_max_planes", c.structure_max_planes);
  f("structure_min_share", c.structure_min_share);
  f("structure_band", c.structure_band);
  f("structure_normal_degrees", c.structure_normal_degrees);
  f("structure_reach", c.structure_reach);
  f("structure_contact", c.structure_contact);
  f("structure_margin_cells", c.structure_margin_cells);
  f("structure_contact_min_degrees", c.structure_contact_min_degrees);
  f("structure_min_standing", c.structure_min_standing);
  f("structure_max_behind", c.structure_max_behind);
  f("structure_enclosing", c.structure_enclosing);
  f("structure_span", c.structure_span);
  f("structure_hypotheses", c.structure_hypotheses);
  f("contact_noise_sigmas", c.contact_noise_sigmas);
  f("contact_min_band", c.contact_min_band);
  f("camera_facing_share", c.camera_facing_share);
  f("remainder_refine", c.remainder_refine);
  f("fragment_max_width", c.fragment_max_width);
  f("fragment_min_elongation", c.fragment_min_elongation);
  f("fragment_max_share", c.fragment_max_share);
  f("min_object_nodes", c.min_object_nodes);
  f("scan_object_min_beams", c.scan_object_min_beams);
  f("scan_leftover_share", c.scan_leftover_share);
  f("min_object_share", c.min_object_share);
  f("seed", c.seed);
}

template <class F>
void visit_fields(PlanesConfig& c, F&& f) {
  f("coarse_threshold", c.coarse_threshold);
  f("fine_threshold", c.fine_threshold);
  f("noise_sigmas", c.noise_sigmas);
  f("face_max_sagitta", c.face_max_sagitta);
  f("face_min_radius_ratio", c.face_min_radius_ratio);
  f("min_plane_fraction", c.min_plane_fraction);
  f("min_plane_points", c.min_plane_points);
  f("max_planes", c.max_planes);
  f("max_rejected_in_row", c.max_rejected_in_row);
  f("ransac_iterations", c.ransac_iterations);
  f("score_samples", c.score_samples);
  f("sample_radius", c.sample_radius);
  f("connectivity", c.connectivity);
  f("boundary_neighbours", c.boundary_neighbours);
  f("boundary_gap_degrees", c.boundary_gap_degrees);
  f("line_distance", c.line_distance);
  f("line_min_support", c.line_min_support);
  f("min_line_angle_degrees", c.min_line_angle_degrees);
  f("seed", c.seed);
}

template <class F>
void visit_fields(KeypointsConfig& c, F&& f) {
  f("neighbourhood", c.neighbourhood);
  f("pursuit_max_steps", c.pursuit_max_steps);
  f("merge_distance", c.merge_distance);
}

template <class F>
void visit_fields(ClassifyConfig& c, F&& f) {
  f("min_points", c.min_points);
  f("border_curvature", c.border_curvature);
  f("corner_gap_degrees", c.corner_gap_degrees);
  f("inner_exclusion", c.inner_exclusion);
  f("apex_candidates", c.apex_candidates);
  f("sphere_max_rms", c.sphere_max_rms);
  f("sphere_max_face_fraction", c.sphere_max_face_fraction);
  f("polyhedron_face_fraction", c.polyhedron_face_fraction);
  f("degenerate_thickness", c.degenerate_thickness);
  f("outline_min_share", c.outline_min_share);
  f("outline_circle_rms", c.outline_circle_rms);
  f("outline_circle_harmonic", c.outline_circle_harmonic);
  f("outline_rect_fill", c.outline_rect_fill);
}

template <class F>
void visit_fields(SolveConfig& c, F&& f) {
  f("inlier_distance", c.inlier_distance);
  f("min_inlier_fraction", c.min_inlier_fraction);
  f("parallel_degrees", c.parallel_degrees);
  f("perpendicular_degrees", c.perpendicular_degrees);
  f("apex_conditioning", c.apex_conditioning);
  f("cap_band", c.cap_band);
  f("face_slab", c.face_slab);
  f("open_end_quantile", c.open_end_quantile);
  f("rim_distance", c.rim_distance);
  f("inside_view_share", c.inside_view_share);
  f("container_rim_quantile", c.container_rim_quantile);
  f("side_fit_min_inlier_fraction", c.side_fit_min_inlier_fraction);
  f("second_chance_round_below", c.second_chance_round_below);
  f("min_side_arc_degrees", c.min_side_arc_degrees);
  f("cylinder_refine_band", c.cylinder_refine_band);
  f("cylinder_refine_iterations", c.cylinder_refine_iterations);
  f("frustum_side_samples", c.frustum_side_samples);
  f("cap_circle_agreement", c.cap_circle_agreement);
  f("min_side_share", c.min_side_share);
  f("max_size_ratio", c.max_size_ratio);
  f("sector_min_share", c.sector_min_share);
  f("verify_samples", c.verify_samples);
  f("preferred_margin", c.preferred_margin);
  f("flat_noise_sigmas", c.flat_noise_sigmas);
  f("guessed_side_cost", c.guessed_side_cost);
  f("closer_fit_margin", c.closer_fit_margin);
  f("ambiguity_rms_ratio", c.ambiguity_rms_ratio);
  f("polyhedron_face_share", c.polyhedron_face_share);
  f("min_side_span", c.min_side_span);
  f("extent_hull_samples", c.extent_hull_samples);
  f("solid_min_scan_lines", c.solid_min_scan_lines);
  f("scan_noise_ratio", c.scan_noise_ratio);
  f("free_space_max_share", c.free_space_max_share);
  f("off_surface_max_share", c.off_surface_max_share);
  f("off_surface_distance", c.off_surface_distance);
  f("apex_gap", c.apex_gap);
  f("cone_tip_gap", c.cone_tip_gap);
  f("frustum_min_taper", c.frustum_min_taper);
  f("frustum_min_top_share", c.frustum_min_top_share);
  f("frustum_side_fill", c.frustum_side_fill);
  f("regular_tolerance", c.regular_tolerance);
  f("triangle_fill_tolerance", c.triangle_fill_tolerance);
  f("curved_side_flat_share", c.curved_side_flat_share);
  f("cylinder_min_side_share", c.cylinder_min_side_share);
  f("tapered_min_rim_reach", c.tapered_min_rim_reach);
  f("side_face_min_share", c.side_face_min_share);
  f("flat_face_fill_cells", c.flat_face_fill_cells);
  f("flat_face_min_fill", c.flat_face_min_fill);
  f("arc_max_scatter_cells", c.arc_max_scatter_cells);
  f("arc_min_sagitta_cells", c.arc_min_sagitta_cells);
  f("box_face_rect_fill", c.box_face_rect_fill);
  f("box_outline_min_share", c.box_outline_min_share);
  f("box_depth_min_share", c.box_depth_min_share);
  f("stray_face_degrees", c.stray_face_degrees);
  f("stray_face_share", c.stray_face_share);
  f("box_slanted_width_ratio", c.box_slanted_width_ratio);
  f("box_edge_distance", c.box_edge_distance);
  f("box_step_min_share", c.box_step_min_share);
  f("box_step_depth", c.box_step_depth);
  f("box_step_share", c.box_step_share);
  f("prism_side_fill", c.prism_side_fill);
  f("cap_section_fill", c.cap_section_fill);
  f("prism_run_gap", c.prism_run_gap);
  f("prism_corner_gap", c.prism_corner_gap);
  f("prism_outline_cell", c.prism_outline_cell);
  f("prism_min_turn_degrees", c.prism_min_turn_degrees);
  f("prism_notch_outside_share", c.prism_notch_outside_share);
  f("prism_notch_min_share", c.prism_notch_min_share);
  f("prism_corner_cut_cells", c.prism_corner_cut_cells);
  f("prism_border_band_cells", c.prism_border_band_cells);
  f("prism_join_evidence", c.prism_join_evidence);
  f("prism_guessed_slack", c.prism_guessed_slack);
}

template <class F>
void visit_fields(Ros2Config& c, F&& f) {
  f("input_topics", c.input_topics);
  f("detections_topic", c.detections_topic);
  f("markers_topic", c.markers_topic);
  f("file_frame_id", c.file_frame_id);
  f("marker_alpha", c.marker_alpha);
  f("extent_line_width", c.extent_line_width);
  f("label_height", c.label_height);
  f("label_fallback_height", c.label_fallback_height);
  f("circle_segments", c.circle_segments);
}

// Calls f(section_name, section_struct) for every section.
template <class F>
void visit_sections(PipelineConfig& c, F&& f) {
  f("input", c.input);
  f("execution", c.execution);
  f("preprocess", c.preprocess);
  f("segment", c.segment);
  f("planes", c.planes);
  f("keypoints", c.keypoints);
  f("classify", c.classify);
  f("solve", c.solve);
  f("ros2", c.ros2);
}

}  // namespace cloudshape::config
