// A cloud scene against ground-truth boxes given in another frame (the HOPE frame):
//  1. register the box centres (unknown correspondences, register_unmatched) and report
//     the residual;
//  2. refine the transform by ICP of the object points against the true box surfaces;
//  3. match each true box to the cluster holding most of its points and report the errors.
#pragma once

#include <vector>

#include "stdlib/tabletop/perception/scene_from_cloud.h"
#include "stdlib/tabletop/perception/surface_registration.h"
#include "stdlib/tabletop/perception/truth_eval.h"

namespace ksmc::stdlib::tabletop::perception {

struct CloudTruth {
  TruthReport by_centres;     // step 1 (matching and errors by nearest registered centre)
  SurfaceFit surfaces;        // step 2
  TruthReport by_points;      // step 3, under the refined transform
  Eigen::Isometry3d table_in_truth = Eigen::Isometry3d::Identity();
};

// `gate`: centre matching distance; `surface_gate`: ICP / membership distance [m].
CloudTruth evaluate_cloud_scene(const CloudScene& cs, const std::vector<TruthBox>& truth, double gate = 0.05,
                                double surface_gate = 0.02);

}  // namespace ksmc::stdlib::tabletop::perception
