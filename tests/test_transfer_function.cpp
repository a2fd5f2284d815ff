#include <cmath>
#include <fstream>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "base/error.hpp"
#include "optics/segment_integral.hpp"
#include "optics/transfer_function.hpp"
#include "scene/transfer_function_json.hpp"
#include "test_util.hpp"

using namespace cellproj;

TEST(TransferFunction, PiecewiseLinearAndClamped) {
  const TransferFunction tf({{0.0, {0, 0, 0}}, {1.0, {1, 0.5, 0}}}, {{0.0, 1.0}, {2.0, 5.0}});
  EXPECT_DOUBLE_EQ(tf.color(0.5).r, 0.5);
  EXPECT_DOUBLE_EQ(tf.color(-3).r, 0.0);
  EXPECT_DOUBLE_EQ(tf.color(7).g, 0.5);
  EXPECT_DOUBLE_EQ(tf.extinction(1.0), 3.0);
  EXPECT_DOUBLE_EQ(tf.extinction(9.0), 5.0);
  EXPECT_EQ(tf.breakpoints(), (std::vector<double>{0.0, 1.0, 2.0}));
}

TEST(TransferFunction, StepTakesTheRightValueAndPiecesTheirOwnSide) {
  const TransferFunction tf({{0.0, {1, 1, 1}}}, {{0.0, 0.0}, {0.5, 0.0}, {0.5, 8.0}, {1.0, 8.0}});
  EXPECT_DOUBLE_EQ(tf.extinction(0.5), 8.0);
  EXPECT_DOUBLE_EQ(tf.extinction(0.4999), 0.0);
  const auto below = tf.piece(0.2, 0.5), above = tf.piece(0.5, 0.9);
  EXPECT_DOUBLE_EQ(below.kb, 0.0);  // the limit from below, not the value at the step
  EXPECT_DOUBLE_EQ(above.ka, 8.0);
}

TEST(TransferFunction, OneUlpPieceBelowAStepKeepsItsSide) {
  // [0.5 - 2^-54, 0.5] lies below the step at 0.5, but its midpoint rounds to 0.5 itself: the
  // piece takes the interval it was cut in, not the one its midpoint falls in.
  const TransferFunction tf({{0.0, {1, 1, 1}}}, {{0.0, 1.0}, {0.5, 1.0}, {0.5, 5.0}, {1.0, 5.0}});
  const double below = std::nextafter(0.5, 0.0);
  ASSERT_EQ(0.5 * (below + 0.5), 0.5);
  int pieces = 0;
  for_each_linear_piece(tf, below, 0.5, [&](const TransferFunction::Ends& e, double fraction) {
    EXPECT_EQ(e.ka, 1.0);
    EXPECT_EQ(e.kb, 1.0);
    EXPECT_EQ(fraction, 1.0);
    ++pieces;
  });
  EXPECT_EQ(pieces, 1);
  for_each_linear_piece(tf, 0.5, below, [&](const TransferFunction::Ends& e, double) {  // the other way
    EXPECT_EQ(e.ka, 1.0);
    EXPECT_EQ(e.kb, 1.0);
  });
}

TEST(TransferFunction, BadInputIsRejectedWithContext) {
  auto msg = [](auto f) {
    try {
      f();
    } catch (const InputError& e) {
      return std::string(e.what());
    }
    return std::string("no error");
  };
  EXPECT_NE(msg([] { TransferFunction({}, {{0, 1}}); }).find("at least one"), std::string::npos);
  EXPECT_NE(msg([] { TransferFunction({{0, {1.5, 0, 0}}}, {{0, 1}}); }).find("outside [0, 1]"), std::string::npos);
  EXPECT_NE(msg([] { TransferFunction({{0, {1, 0, 0}}}, {{0, -1}}); }).find(">= 0"), std::string::npos);
  EXPECT_NE(msg([] {
              TransferFunction({{1, {1, 0, 0}}, {0, {1, 0, 0}}}, {{0, 1}});
            }).find("increasing"),
            std::string::npos);
  EXPECT_NE(msg([] { TransferFunction({{0, {1, 0, 0}}}, {{0, NAN}}); }).find("finite"), std::string::npos);
  const auto j = nlohmann::json::parse(R"({"color": [[0, 1, 0]], "extinction": [[0, 1]]})");
  EXPECT_NE(
      msg([&] { transfer_function_from_json(j, "s.json", ".", 0, 1); }).find("s.json: transfer_function.color[0]"),
      std::string::npos);
  const auto k = nlohmann::json::parse(R"({"color": [[0, 1, 0, 0]], "extinction": [[0, 1]], "opacity": 1})");
  EXPECT_NE(msg([&] { transfer_function_from_json(k, "s.json", ".", 0, 1); }).find("unknown key 'opacity'"),
            std::string::npos);
}

TEST(TransferFunction, ParaViewPresetIsStretchedOverTheRange) {
  test::TempDir dir;
  std::ofstream(dir.file("preset.json")) << R"([{"Name": "Other", "RGBPoints": [0, 0, 0, 0, 1, 1, 1, 1]},
      {"Name": "Cool", "ColorSpace": "RGB", "RGBPoints": [-1, 0, 0, 1, 1, 1, 0, 0]}])";
  const auto j =
      nlohmann::json::parse(R"({"color_preset": {"file": "preset.json", "name": "Cool"}, "extinction": [[0, 1]]})");
  const auto file_dir = std::filesystem::path(dir.file("preset.json")).parent_path().string();
  const TransferFunction tf = transfer_function_from_json(j, "s.json", file_dir, 10.0, 20.0);
  EXPECT_DOUBLE_EQ(tf.color(10.0).b, 1.0);
  EXPECT_DOUBLE_EQ(tf.color(15.0).r, 0.5);
  EXPECT_DOUBLE_EQ(tf.color(20.0).r, 1.0);
  const auto bad =
      nlohmann::json::parse(R"({"color_preset": {"file": "preset.json", "name": "Nope"}, "extinction": [[0, 1]]})");
  try {
    transfer_function_from_json(bad, "s.json", file_dir, 0, 1);
    FAIL();
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("the maps are: Other, Cool"), std::string::npos) << e.what();
  }
  // A preset's wrong types are InputErrors naming the key, not JSON library exceptions.
  std::ofstream(dir.file("text.json")) << R"([{"Name": "T", "RGBPoints": [0, "red", 0, 0, 1, 1, 1, 1]}])";
  for (const char* spec : {R"({"color_preset": {"file": "text.json"}, "extinction": [[0, 1]]})",
                           R"({"color_preset": {"file": 7}, "extinction": [[0, 1]]})",
                           R"({"color_preset": {"file": "text.json", "name": 3}, "extinction": [[0, 1]]})"}) {
    try {
      transfer_function_from_json(nlohmann::json::parse(spec), "s.json", file_dir, 0, 1);
      ADD_FAILURE() << spec;
    } catch (const InputError& e) {
      EXPECT_TRUE(std::string(e.what()).find("expected a") != std::string::npos) << e.what();
    }
  }
}
