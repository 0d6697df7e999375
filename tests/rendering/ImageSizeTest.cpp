// SPDX-License-Identifier: AGPL-3.0-or-later
#include <gtest/gtest.h>

#include "tetskin/rendering/ImageSize.h"

namespace tetskin {
namespace {

TEST(ImageSize, ReadsWidthAndHeight) {
  const auto size = parseImageSize("1280x800");
  ASSERT_TRUE(size.has_value());
  EXPECT_EQ(size->width, 1280);
  EXPECT_EQ(size->height, 800);
  EXPECT_TRUE(parseImageSize("16x8192").has_value());  // both ends of the range
  EXPECT_EQ(imageSizeProblem("320x240"), "");
}

TEST(ImageSize, RefusesAnythingElse) {
  for (const char* text :
       {"", "x", "320", "320x", "x240", "320x240x", "320X240", " 320x240", "320 x240", "+320x240",
        "-320x240", "320.0x240", "0x0", "15x240", "320x8193", "99999999999x240"})
    EXPECT_FALSE(parseImageSize(text).has_value()) << "'" << text << "'";
  EXPECT_EQ(imageSizeProblem("0x0"), "'0x0' is not WIDTHxHEIGHT with both in [16, 8192]");
}

}  // namespace
}  // namespace tetskin
