// All three methods on the paper's own training rows (Table I, shared/data/paper-tables).

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>

#include "ballsight/calib/ground_error.hpp"
#include "ballsight/calib/omni_model_fit.hpp"
#include "ballsight/calib/sample_csv.hpp"
#include "shared_data.hpp"
#include "skip.hpp"

namespace ballsight {
namespace {

TEST(PaperTableI, EveryMethodFitsAndPredicts) {
  const std::filesystem::path path =
      test::shared_data_dir() / "paper-tables" / "table1_training_samples.csv";
  if (!std::filesystem::exists(path)) BALLSIGHT_SKIP() << "no " << path << " (shared data absent)";
  const std::vector<PolarSample> samples = read_polar_samples_csv(path);
  ASSERT_EQ(samples.size(), 17u);
  const OmniImage image = omni_image_for_samples(samples, std::nullopt, std::nullopt);
  OmniFitOptions options;
  for (const OmniMethod method :
       {OmniMethod::kPoly, OmniMethod::kPaperMlp, OmniMethod::kBallsight}) {
    SCOPED_TRACE(omni_method_name(method));
    const auto model = fit_omni_model(method, samples, image, options);
    const GroundErrors errors = sample_errors(*model, samples);
    EXPECT_EQ(errors.out_of_range, 0u);
    EXPECT_EQ(errors.unmapped, 0u);
    // The rows scatter (20 deg: 127 px at 110 cm, others ~105 px); a fit that follows the
    // bulk stays within a few cm of most rows.
    EXPECT_LT(errors.distance_cm.median, 8.0);
    EXPECT_LT(errors.distance_cm.max, 30.0);
    for (double r = model->domain().valid_radius.min_px; r <= model->domain().valid_radius.max_px;
         r += 1.0) {
      EXPECT_TRUE(std::isfinite(model->predict(5.0, r).distance_cm)) << r;
    }
  }
}

}  // namespace
}  // namespace ballsight
