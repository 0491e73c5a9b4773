#pragma once
// A ballsight lookup table seen through the model interface, so a table can be applied to samples
// like any fitted model: the query's pixel around the table's centre, the table's interpolated
// ground point, its distance and bearing.

#include "ballsight/calib/omni_ground_model.hpp"
#include "ballsight/camera/ground_map.hpp"

namespace ballsight {

class GroundMapModel final : public OmniGroundModel {
 public:
  explicit GroundMapModel(GroundMap map);

  std::string_view name() const override { return map_.info().method; }
  const OmniModelDomain& domain() const override { return domain_; }
  GroundPrediction predict(double theta_deg, double radius_px) const override;
  nlohmann::json parameters_json() const override;
  std::optional<double> viewpoint_height_cm() const override;

 private:
  GroundMap map_;
  OmniModelDomain domain_;
};

}  // namespace ballsight
