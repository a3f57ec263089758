// Boxes that do not stand upright (leaning on a neighbour, fallen over an edge). The
// upright fit imposes one axis along the table normal, so a leaning box gets a loose
// upright box around it. Here the cluster's planar faces decide: a large face whose
// normal is neither vertical nor horizontal belongs to a tilted box. Its orientation is
// that face's normal and the normal of an adjacent perpendicular face (the box's other
// visible faces), its extents are the trimmed extents of those faces' points along the
// three axes. The cluster's points explained by that box are removed; what is left (the
// upright neighbour it leans on, more tilted boxes) is fitted again by the caller. A box that
// leans about the normal of its one large visible face shows no tilted large face: that face
// stays vertical, but its outline is a turned rectangle, which then gives the orientation.
#pragma once

#include <optional>

#include "stdlib/tabletop/perception/box_fit.h"
#include "stdlib/tabletop/perception/planar_faces.h"

namespace ksmc::stdlib::tabletop::perception {

// The face options of the tilted fit: a tilted face is often seen at a slant, in rows up to
// twice the growing radius apart (FaceOptions::row_factor).
inline FaceOptions slanted_faces() {
  FaceOptions f;
  f.row_factor = 2.0;
  return f;
}

struct TiltOptions {
  FaceOptions faces = slanted_faces();
  double min_tilt_deg = 5.0;        // a face this far from both horizontal and vertical is tilted
  bool join_split = true;           // tilted faces cut in two by a seam are one (join_coplanar_faces;
                                    // not the vertical and horizontal ones: an upright neighbour's
                                    // face cut by the leaning box's shadow stays two)
  std::size_t min_face_points = 80; // smaller tilted faces do not start a tilted box
  double min_face_side = 0.03;      // m, nor do faces narrower than this (bevels, a carton's gable top)
  double perpendicular_deg = 12.0;  // faces of one box: normals perpendicular within this
  double adjacent = 0.03;           // m, a face of the same box has a point this close to the first face
                                    // (edges are in no face: two normal radii apart)
  double side_tolerance = 0.005;    // m; two faces of one box each lie on one side of the other's plane
  double edge_gap = 0.012;          // m; ... and each comes this close to the other's plane (their edge)
  double max_overreach = 0.03;      // m; ... and runs past the seed's upper end along that edge by at most
                                    // this (both ends along a level edge; 0: off)
  double trim = 0.003;              // quantile pulled in on each side of each extent
  double own_margin = 0.008;        // m, cluster points this close to the box are its own
  double min_size = 0.005;          // m
  double support_gap = 0.006;       // m; a box whose lowest corner is higher is grown to the table
  double max_support_growth = 0.15; // m
  std::size_t max_support_points = 10; // ... unless the grown part holds more cluster points than this
  double fill_cell = 0.008;         // m; a face's rows across each in-plane axis are this wide ...
  double fill_ratio = 0.35;         // ... and it keeps the rows at least this long against its longest
  double probe_voxel = 0.008;       // m; the faces are first looked for on a copy this sparse
  bool leaning_outlines = true;     // with no tilted face, a vertical face whose outline leans starts one
  double outline_ratio = 0.8;       // ... when its turned rectangle covers at most this of the upright one
  double interior_depth = 0.010;    // m; a box whose own points lie this far inside it ...
  double max_interior = 0.2;        // ... more often than this is not the box they were seen on (the
                                    // sensor sees surfaces): a slope of a non-box shape, the gable top
                                    // of a carton seen by a Kinect, tilts no box
};

struct TiltedFit {
  UprightBox box;   // pose in the table frame with any orientation (axis 2: the axis nearest the normal)
  Points rest;      // the cluster's points not within own_margin of the box
};

// The tilted box of the cluster's largest tilted face, or nothing when every large face
// is horizontal or vertical (an upright box, or a stack of them: fit_stacked_boxes), or
// when the box it gives has its own points inside it rather than on its faces.
std::optional<TiltedFit> fit_tilted_box(const Points& points, const TiltOptions& options = {});

// Axes (columns) and sizes turned into the canonical form used for every box: axis 2 is
// the axis nearest the table normal (pointing up), axis 0 the one of the other two with
// the larger x component (pointing to +x), right-handed.
void canonical_axes(Eigen::Matrix3d& axes, Eigen::Vector3d& size);

}  // namespace ksmc::stdlib::tabletop::perception
