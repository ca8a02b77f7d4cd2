// Planes, key-points and the classification across the wire (the stages' intermediate data).
#include "dds/convert.hpp"

namespace cloudshape::dds {
namespace {

std::array<double, 3> arr(const Eigen::Vector3d& v) { return {v.x(), v.y(), v.z()}; }
Eigen::Vector3d vec(const std::array<double, 3>& a) { return {a[0], a[1], a[2]}; }

msg::KeypointType to_msg(pipeline::KeypointType t) {
  switch (t) {
    case pipeline::KeypointType::corner: return msg::CORNER;
    case pipeline::KeypointType::edge: return msg::EDGE;
    case pipeline::KeypointType::border: return msg::BORDER;
  }
  return msg::EDGE;
}

pipeline::KeypointType from_msg(msg::KeypointType t) {
  switch (t) {
    case msg::CORNER: return pipeline::KeypointType::corner;
    case msg::BORDER: return pipeline::KeypointType::border;
    default: return pipeline::KeypointType::edge;
  }
}

}  // namespace

pipeline::Shape shape_from_name(const std::string& name) {
  for (pipeline::Shape s : pipeline::kNamedShapes) {
    if (pipeline::shape_name(s) == name) return s;
  }
  return pipeline::Shape::unknown;
}

msg::PlaneSegmentation to_msg(const pipeline::PlaneSegmentation& s) {
  msg::PlaneSegmentation m;
  m.planes().reserve(s.planes.size());
  for (const pipeline::DetectedPlane& p : s.planes) {
    msg::DetectedPlane mp;
    mp.normal(arr(p.plane.normal));
    mp.offset(p.plane.offset);
    mp.inliers(p.inliers);
    mp.boundary(p.boundary);
    mp.is_face(p.is_face);
    mp.curvature_sagitta(p.curvature_sagitta);
    m.planes().push_back(std::move(mp));
  }
  for (const pipeline::PlaneLine& l : s.lines) {
    msg::PlaneLine ml;
    ml.point(arr(l.line.point));
    ml.direction(arr(l.line.direction));
    ml.t_min(l.t_min);
    ml.t_max(l.t_max);
    ml.plane_a(l.plane_a);
    ml.plane_b(l.plane_b);
    m.lines().push_back(ml);
  }
  m.labels(s.labels);
  m.view_noise(s.view_noise);
  return m;
}

pipeline::PlaneSegmentation from_msg(const msg::PlaneSegmentation& m) {
  pipeline::PlaneSegmentation s;
  s.planes.reserve(m.planes().size());
  for (const msg::DetectedPlane& mp : m.planes()) {
    pipeline::DetectedPlane p;
    p.plane.normal = vec(mp.normal());
    p.plane.offset = mp.offset();
    p.inliers = mp.inliers();
    p.boundary = mp.boundary();
    p.is_face = mp.is_face();
    p.curvature_sagitta = mp.curvature_sagitta();
    s.planes.push_back(std::move(p));
  }
  for (const msg::PlaneLine& ml : m.lines()) {
    pipeline::PlaneLine l;
    l.line.point = vec(ml.point());
    l.line.direction = vec(ml.direction());
    l.t_min = ml.t_min();
    l.t_max = ml.t_max();
    l.plane_a = ml.plane_a();
    l.plane_b = ml.plane_b();
    s.lines.push_back(l);
  }
  s.labels = m.labels();
  s.view_noise = m.view_noise();
  return s;
}

msg::KeypointSet to_msg(const pipeline::KeypointSet& k) {
  msg::KeypointSet m;
  m.reference_center(arr(k.reference.center));
  m.reference_radius(k.reference.radius);
  for (const pipeline::Keypoint& kp : k.keypoints) {
    msg::Keypoint mk;
    mk.index(kp.index);
    mk.neighbourhood(kp.neighbourhood);
    m.keypoints().push_back(std::move(mk));
  }
  return m;
}

pipeline::KeypointSet from_msg(const msg::KeypointSet& m) {
  pipeline::KeypointSet k;
  k.reference.center = vec(m.reference_center());
  k.reference.radius = m.reference_radius();
  for (const msg::Keypoint& mk : m.keypoints()) {
    pipeline::Keypoint kp;
    kp.index = mk.index();
    kp.neighbourhood = mk.neighbourhood();
    k.keypoints.push_back(std::move(kp));
  }
  return k;
}

msg::ClassificationData to_msg(const pipeline::Classification& c) {
  msg::ClassificationData m;
  for (const pipeline::TypedKeypoint& t : c.keypoints) {
    msg::TypedKeypoint mt;
    mt.index(t.index);
    mt.type(to_msg(t.type));
    mt.curvature(t.curvature);
    mt.gap_degrees(t.gap_degrees);
    m.keypoints().push_back(mt);
  }
  m.counts().corner(c.counts.corner);
  m.counts().edge(c.counts.edge);
  m.counts().border(c.counts.border);
  m.shape(pipeline::shape_name(c.shape));
  for (pipeline::Shape s : c.candidates) m.candidates().push_back(pipeline::shape_name(s));
  m.reason(c.reason);
  m.face_fraction(c.face_fraction);
  m.sphere_test(c.sphere_test);
  m.cap_plane(c.cap_plane ? static_cast<std::int32_t>(*c.cap_plane) : -1);
  const pipeline::FaceOutline& o = c.cap_outline;
  m.cap_outline().kind(o.kind == pipeline::OutlineKind::circle      ? msg::CIRCLE
                       : o.kind == pipeline::OutlineKind::rectangle ? msg::RECTANGLE
                                                                    : msg::UNDECIDED);
  m.cap_outline().center({o.center.x(), o.center.y(), o.center.z()});
  m.cap_outline().radius(o.radius);
  m.cap_outline().circle_rms(o.circle_rms);
  m.cap_outline().rect_fill(o.rect_fill);
  m.cap_outline().polygon_harmonic(o.polygon_harmonic);
  m.rectangular_face(c.rectangular_face);
  return m;
}

pipeline::Classification from_msg(const msg::ClassificationData& m) {
  pipeline::Classification c;
  for (const msg::TypedKeypoint& mt : m.keypoints()) {
    pipeline::TypedKeypoint t;
    t.index = mt.index();
    t.type = from_msg(mt.type());
    t.curvature = mt.curvature();
    t.gap_degrees = mt.gap_degrees();
    c.keypoints.push_back(t);
  }
  c.counts.corner = m.counts().corner();
  c.counts.edge = m.counts().edge();
  c.counts.border = m.counts().border();
  c.shape = shape_from_name(m.shape());
  for (const std::string& s : m.candidates()) c.candidates.push_back(shape_from_name(s));
  c.reason = m.reason();
  c.face_fraction = m.face_fraction();
  c.sphere_test = m.sphere_test();
  if (m.cap_plane() >= 0) c.cap_plane = static_cast<std::size_t>(m.cap_plane());
  const msg::FaceOutline& o = m.cap_outline();
  c.cap_outline.kind = o.kind() == msg::CIRCLE      ? pipeline::OutlineKind::circle
                       : o.kind() == msg::RECTANGLE ? pipeline::OutlineKind::rectangle
                                                    : pipeline::OutlineKind::undecided;
  c.cap_outline.center = Point(o.center()[0], o.center()[1], o.center()[2]);
  c.cap_outline.radius = o.radius();
  c.cap_outline.circle_rms = o.circle_rms();
  c.cap_outline.rect_fill = o.rect_fill();
  c.cap_outline.polygon_harmonic = o.polygon_harmonic();
  c.rectangular_face = m.rectangular_face();
  return c;
}

}  // namespace cloudshape::dds
