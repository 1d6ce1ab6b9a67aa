// The validation modes' spellings (renderer/vk/validation_mode.h) on the command line and in RAYLAB_VALIDATE.
#include <gtest/gtest.h>

#include "app/cli_options.h"
#include "renderer/vk/validation_mode.h"

namespace raylab {

TEST(ValidationMode, Spellings) {
  EXPECT_EQ(parseValidationMode("1"), ValidationMode::Sync);
  EXPECT_EQ(parseValidationMode("sync"), ValidationMode::Sync);
  EXPECT_EQ(parseValidationMode("gpu-av"), ValidationMode::GpuAssisted);
  EXPECT_EQ(parseValidationMode("0"), ValidationMode::Off);
  EXPECT_EQ(parseValidationMode(""), ValidationMode::Off);
  EXPECT_FALSE(parseValidationMode("gpuav").has_value());
  EXPECT_STREQ(validationModeName(ValidationMode::GpuAssisted), "gpu-av");
}

TEST(ValidationMode, CommandLine) {
  EXPECT_EQ(parseCommonOptions({}).validation, ValidationMode::Off);
  EXPECT_EQ(parseCommonOptions({"--validate"}).validation, ValidationMode::Sync);
  EXPECT_EQ(parseCommonOptions({"--validate=sync"}).validation, ValidationMode::Sync);
  EXPECT_EQ(parseCommonOptions({"--validate=gpu-av"}).validation, ValidationMode::GpuAssisted);
  EXPECT_THROW(parseCommonOptions({"--validate=all"}), UsageError);
}

}  // namespace raylab
