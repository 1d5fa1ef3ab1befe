// The fuzz build's list of shading model names (shading_model_names.hpp) is the real table's,
// row for row, so the scene fuzzer accepts exactly the scenes crosscheck accepts.
#include "shading_model_names.hpp"

#include <shading_models.hpp>

#include <gtest/gtest.h>

#include <iterator>

TEST(FuzzShadingModelNames, AreTheRealTable) {
  const auto real = shaders::shadingModels();
  ASSERT_EQ(real.size(), std::size(fuzz::kShadingModelNames));
  for (std::size_t i = 0; i < real.size(); ++i) {
    EXPECT_EQ(real[i].name, fuzz::kShadingModelNames[i].name) << i;
    EXPECT_EQ(real[i].meshInputs, fuzz::kShadingModelNames[i].meshInputs) << real[i].name;
    EXPECT_EQ(real[i].textures, fuzz::kShadingModelNames[i].textures) << real[i].name;
    EXPECT_EQ(real[i].shadowMap, fuzz::kShadingModelNames[i].shadowMap) << real[i].name;
    EXPECT_EQ(real[i].depthPassOnly, fuzz::kShadingModelNames[i].depthPassOnly) << real[i].name;
    EXPECT_EQ(real[i].colourOutputs, fuzz::kShadingModelNames[i].colourOutputs) << real[i].name;
  }
}
