// SPDX-License-Identifier: AGPL-3.0-or-later
// The C++ side of the GPU paths and the shaders agree (GpuContract.h): every
// buffer a shader binds names a slot of the contract, never a number, and
// every vertex attribute the mappers feed is declared by a shader. No
// OpenGL needed: the rendering tests draw with them.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <regex>
#include <set>
#include <sstream>
#include <string>

#include "GpuContract.h"

namespace tetskin::gpu {
namespace {

std::string shadersText() {
  std::string all;
  for (const auto& entry :
       std::filesystem::directory_iterator(std::string(TETSKIN_SOURCE_DIR) + "/shaders"))
    if (entry.path().extension() == ".glsl") {
      std::ifstream in(entry.path());
      std::stringstream text;
      text << in.rdbuf();
      all += text.str();
    }
  return all;
}

TEST(GpuContract, EveryShaderBufferNamesASlotOfTheContract) {
  std::set<std::string> defines;
  std::set<unsigned> numbers;
  for (const SlotName& s : kSlots) {
    defines.insert(s.define);
    numbers.insert(index(s.slot));
  }
  EXPECT_EQ(numbers.size(), kSlots.size());  // no two slots share a binding point
  const std::string text = shadersText();
  const std::regex binding(R"(binding\s*=\s*([A-Za-z0-9_]+))");
  int bindings = 0;
  for (auto it = std::sregex_iterator(text.begin(), text.end(), binding);
       it != std::sregex_iterator(); ++it, ++bindings)
    EXPECT_TRUE(defines.count((*it)[1].str()) == 1)
        << "a shader binds a buffer at " << (*it)[1].str() << ", not a slot of GpuContract.h";
  EXPECT_EQ(bindings, 12);  // gpu-2pass's three compute passes
}

TEST(GpuContract, SlotsReachTheShaderAfterItsVersionLine) {
  const std::string source = withSlots("#version 430\nlayout(local_size_x = 64) in;\n");
  EXPECT_EQ(source.rfind("#version 430\n", 0), 0u);
  for (const SlotName& s : kSlots)
    EXPECT_NE(source.find("#define " + std::string(s.define) + " " + std::to_string(index(s.slot)) +
                          "\n"),
              std::string::npos)
        << s.define;
  EXPECT_NE(source.find("\nlayout(local_size_x = 64) in;\n"), std::string::npos);
}

TEST(GpuContract, EveryAttributeTheMappersFeedIsDeclaredByAShader) {
  const std::string text = shadersText();
  for (const char* name : attribute::kAll)
    EXPECT_TRUE(std::regex_search(
        text, std::regex(std::string(R"((^|\n)in\s+(float|vec[234])\s+)") + name + R"(\s*;)")))
        << name << " is fed to no shader input";
}

}  // namespace
}  // namespace tetskin::gpu
