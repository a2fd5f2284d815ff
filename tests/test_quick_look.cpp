// The pieces of a first picture without a scene: built-in colour maps, named views, the legend.
#include <gtest/gtest.h>

#include <glm/geometric.hpp>

#include "base/error.hpp"
#include "mesh/generate.hpp"
#include "optics/colormaps.hpp"
#include "render/settings_table.hpp"
#include "scene/prepare.hpp"
#include "scene/quick_scene.hpp"
#include "scene/scene_file.hpp"
#include "test_util.hpp"
#include "view/annotations.hpp"
#include "view/caption.hpp"
#include "view/color_bar.hpp"

namespace cellproj {
namespace {

TEST(Colormaps, AreStretchedOverTheRangeAndFoundByEitherName) {
  const auto viridis = colormap("Viridis (matplotlib)", -2.0, 6.0);
  ASSERT_EQ(viridis.size(), 17u);
  EXPECT_DOUBLE_EQ(viridis.front().s, -2.0);
  EXPECT_DOUBLE_EQ(viridis.back().s, 6.0);
  EXPECT_NEAR(viridis.front().rgb.r, 0.267, 1e-3);  // matplotlib's viridis(0) = (0.267, 0.005, 0.329)
  EXPECT_NEAR(viridis.back().rgb.g, 0.906, 1e-3);   // viridis(1) = (0.993, 0.906, 0.144)
  const auto alias = colormap("VIRIDIS", -2.0, 6.0);
  EXPECT_EQ(alias.back().rgb, viridis.back().rgb);
  const auto jet = colormap("jet", 0.0, 1.0);
  EXPECT_NEAR(jet[3].s, 0.492063, 1e-6);             // ParaView's Jet knots, exactly
  EXPECT_EQ(colormap("gray", 3.0, 3.0).size(), 1u);  // a constant field: one colour
  EXPECT_THROW(colormap("nope", 0, 1), InputError);
  for (const auto& name : colormap_list()) EXPECT_NO_THROW(TransferFunction(colormap(name, 0, 1), {{0, 1}}));
}

TEST(QuickLook, NamedViewsLookAlongTheirAxisAndFrameTheBox) {
  const glm::dvec3 lo(-1, -2, -3), hi(1, 2, 3);
  const Camera c = view_camera("+x", lo, hi, 1.0);
  const glm::dvec3 dir = glm::normalize(c.target - c.eye);
  EXPECT_NEAR(dir.x, 1.0, 1e-12);  // ParaView's +X: looking along +x
  EXPECT_NEAR(c.up.z, 1.0, 1e-12);
  EXPECT_GE(c.height, glm::length(hi - lo));  // the whole box's diagonal fits
  EXPECT_NEAR(glm::normalize(view_camera("-z", lo, hi, 1.0).target - view_camera("-z", lo, hi, 1.0).eye).z, -1.0,
              1e-12);
  EXPECT_THROW(view_camera("up", lo, hi, 1.0), InputError);
}

TEST(RenderOptions, AreSetByEitherSpellingAndCheckedByName) {
  RenderOptions o;
  set_option(o, "table_size", "64");
  set_option(o, "slice-axis", "view");
  EXPECT_EQ(option_text(o, "table-size"), "64");
  EXPECT_EQ(option_text(o, "sort"), "auto");  // not given: its default
  EXPECT_EQ(o.given, (std::vector<std::string>{"table-size", "slice-axis"}));
  EXPECT_EQ(settings_from(o).projection.table_size, 64);
  try {
    set_option(o, "slices", "12x");
    FAIL();
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("setting 'slices': expected an integer, got '12x'"), std::string::npos);
  }
  EXPECT_THROW(set_option(o, "colour", "red"), InputError);
  EXPECT_THROW(set_option(o, "sort", "bogus"), InputError);
  EXPECT_EQ(option_text(o, "sort"), "auto");  // a bad value is not kept
}

TEST(ColorBar, DrawsTheColoursInOrderOnTheRightAndLeavesTheRestAlone) {
  Rgb8Image img{200, 160, std::vector<unsigned char>(200 * 160 * 3, 7)};
  ColorBar bar;
  bar.colors = {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}};  // low red, high blue
  bar.lo = 0;
  bar.hi = 1;
  bar.title = "T";
  if (default_font().empty()) GTEST_SKIP() << "no font found at build time";
  draw_color_bar(img, bar);
  // The left half holds no part of the legend.
  for (int y = 0; y < img.height; ++y)
    for (int x = 0; x < img.width / 2; ++x) ASSERT_EQ(img.pixel(x, y)[0], 7) << x << "," << y;
  // Down the bar's middle column, blue above green above red.
  int blue = -1, green = -1, red = -1;
  for (int x = img.width / 2; x < img.width && red < 0; ++x)
    for (int y = 0; y < img.height; ++y) {
      const unsigned char* p = img.pixel(x, y);
      if (p[2] == 255 && p[0] == 0 && blue < 0) blue = y;
      if (p[1] == 255 && p[0] == 0 && blue >= 0 && green < 0) green = y;
      if (p[0] == 255 && p[1] == 0 && green >= 0 && red < 0) red = y;
    }
  EXPECT_GE(blue, 0);
  EXPECT_GT(green, blue);
  EXPECT_GT(red, green);
  bar.font = "/nonexistent.ttf";
  EXPECT_THROW(draw_color_bar(img, bar), InputError);
}

// Pictures for slides and compositing tools: a transparent PNG (straight alpha) and 16-bit PNGs
// read back equal the float image to their precision; a legend on a transparent picture is opaque.
TEST(ColorBar, TicksAreTheEndsAndNiceValuesBetween) {
  ColorBar bar;
  bar.lo = 0.0, bar.hi = 1.0;
  const auto texts = [](const std::vector<BarTick>& ticks) {
    std::vector<std::string> out;
    for (const BarTick& t : ticks) out.push_back(t.text);
    return out;
  };
  EXPECT_EQ(texts(bar_ticks(bar, 4, 0.05)), (std::vector<std::string>{"0", "0.2", "0.4", "0.6", "0.8", "1"}));
  bar.lo = 3.1, bar.hi = 97.0;  // the ends as they are, nice values between, none crowding an end
  const std::vector<BarTick> ticks = bar_ticks(bar, 4, 0.1);
  EXPECT_EQ(texts(ticks), (std::vector<std::string>{"3.1", "20", "40", "60", "80", "97"}));
  EXPECT_NEAR(ticks[1].at, (20 - 3.1) / (97 - 3.1), 1e-12);
  // A log bar (log10 of the values): the decades, labelled in the field's units.
  bar.log = true, bar.lo = std::log10(3206.6), bar.hi = std::log10(8.1e6);
  EXPECT_EQ(texts(bar_ticks(bar, 6, 0.05)), (std::vector<std::string>{"3207", "1e+04", "1e+05", "1e+06", "8.1e+06"}));
  bar.lo = 0.0, bar.hi = std::log10(30.0);  // within two decades: 1, 2, 5 times them
  EXPECT_EQ(texts(bar_ticks(bar, 6, 0.05)), (std::vector<std::string>{"1", "2", "5", "10", "20", "30"}));
}

// The legend says what the picture's colours mean: a reduction named, iso-surfaces and layers
// marked in their colours, the colour map left out where the picture has none of it.
TEST(ColorBar, TheLegendOfEachMethodShowsItsColours) {
  PreparedScene p{
      {},       "T", 0.0, 1.0, false, "T", TransferFunction({{0.0, {0, 0, 1}}, {1.0, {1, 0, 0}}}, {{0.0, 1.0}}),
      Camera{}, {},  {}};
  RenderSettings s;
  s.mode = RenderMode::reduction, s.reduction = RayReduction::minimum;
  EXPECT_EQ(color_bar(p, s, glm::dvec3(0.0)).title, "T (minimum along each ray)");
  s.mode = RenderMode::exact;
  s.iso.surfaces = {{0.25, {0, 1, 0}, 0.5, true}, {0.75, {}, 0.5, false}};
  s.iso.volume = false;
  const ColorBar iso = color_bar(p, s, glm::dvec3(0.0));
  ASSERT_EQ(iso.marks.size(), 2u);
  EXPECT_EQ(iso.marks[0].color, glm::dvec3(0, 1, 0));
  EXPECT_EQ(iso.marks[1].color, p.tf.color(0.75));  // the transfer function's where none is given
  EXPECT_FALSE(iso.gradient);
  s.mode = RenderMode::layers, s.layers.iso = 0.5;
  const ColorBar layers = color_bar(p, s, glm::dvec3(0.0));
  EXPECT_FALSE(layers.gradient);
  ASSERT_EQ(layers.marks.size(), 1u);
  EXPECT_EQ(layers.marks[0].value, 0.5);
  if (default_font().empty()) GTEST_SKIP() << "no font";
  Rgb8Image img;  // drawn: the swatch's colour on the bar, the bar's colours nowhere
  img.width = 200, img.height = 200;
  img.rgb.assign(200 * 200 * 3, 0);
  draw_color_bar(img, layers);
  int swatch = 0, red = 0;
  for (int j = 0; j < img.height; ++j)
    for (int i = 0; i < img.width; ++i) {
      const unsigned char* q = img.pixel(i, j);
      swatch += q[0] > 100 && q[1] < 60 && q[2] > 100;  // tf(0.5) = (0.5, 0, 0.5)
      red += q[0] > 200 && q[1] < 60 && q[2] < 60;
    }
  EXPECT_GT(swatch, 10);
  EXPECT_EQ(red, 0);
}

// The outline is the box's edges as the camera sees them; the triad's axes point where the world's
// do, an axis along the view foreshortened to nothing.
TEST(Annotations, TheOutlineFollowsTheBoxAndTheAxesTheWorld) {
  const Camera camera = test::looking_down(4.0);  // x right, y up, the box [-1, 1]^2 the middle half
  Rgb8Image img;
  img.width = img.height = 80;
  img.rgb.assign(80 * 80 * 3, 0);
  Annotations a;
  a.outline = true, a.lo = glm::dvec3(-1), a.hi = glm::dvec3(1), a.color = glm::dvec3(1.0);
  draw_annotations(img, camera, a);
  const auto lit = [&](int i, int j) { return img.pixel(i, j)[0] > 100; };
  EXPECT_TRUE(lit(20, 40) || lit(19, 40));  // the left edge, x = -1 at column 20
  EXPECT_TRUE(lit(40, 20) || lit(40, 19));  // the top edge, y = 1 at row 20
  EXPECT_FALSE(lit(40, 40));                // inside: untouched
  EXPECT_FALSE(lit(5, 40));                 // outside: untouched
  if (default_font().empty()) GTEST_SKIP() << "no font";
  img.rgb.assign(80 * 80 * 3, 0);
  a.outline = false, a.axes = true;
  draw_annotations(img, camera, a);
  int red = 0, green = 0;  // x to the right of the triad's origin (red), y above it (green)
  for (int j = 0; j < 80; ++j)
    for (int i = 0; i < 80; ++i) {
      const unsigned char* q = img.pixel(i, j);
      red += q[0] > 150 && q[1]<100, green += q[1]> 150 && q[0] < 100;
    }
  EXPECT_GT(red, 3);
  EXPECT_GT(green, 3);
}

TEST(SampleFilters, ATentKeepsAConstantAndWeighsItsNeighbours) {
  Image flat(12, 8);
  for (float& v : flat.rgba) v = 0.25f;
  for (float v : downsample(flat, 4, SampleFilter::tent).rgba) EXPECT_NEAR(v, 0.25f, 1e-7);
  // One lit sample column at x = 5 (pixel 1's second sample): the tent gives pixel 0 a share of it
  // (its centre 1.125 pixels of samples away, weight 1 - 0.875 against the others), the box none.
  Image line(12, 4);
  for (int j = 0; j < 4; ++j) line.pixel(5, j)[3] = 1.0f;
  const Image box = downsample(line, 4, SampleFilter::box), tent = downsample(line, 4, SampleFilter::tent);
  EXPECT_EQ(box.pixel(0, 0)[3], 0.0f);
  EXPECT_GT(tent.pixel(0, 0)[3], 0.0f);
  EXPECT_GT(tent.pixel(1, 0)[3], tent.pixel(0, 0)[3]);
}

TEST(Caption, StandsAboveThePictureAndLabelsTheTime) {
  EXPECT_EQ(time_label("t = %.2f", 1.5), "t = 1.50");
  EXPECT_EQ(time_label("%g s (100%%)", 0.25), "0.25 s (100%)");
  for (const char* bad : {"%d", "%s", "t = %.2f %.2f", "%n", "no time", "%.2f%"})
    EXPECT_NE(test::input_error([&] { time_label(bad, 1.0); }).find("setting 'time-format'"), std::string::npos) << bad;
  if (default_font().empty()) GTEST_SKIP() << "no font";
  Rgb8Image picture;
  picture.width = 40, picture.height = 30;
  picture.rgb.assign(40 * 30 * 3, 200);
  const Caption caption{"Title", "t = 1.00", glm::dvec3(1.0), ""};
  Rgb8Image out = above_caption(picture, caption, glm::dvec3(0.0));
  const int strip = out.height - picture.height;
  ASSERT_EQ(out.width, picture.width);
  ASSERT_GT(strip, 0);
  for (int j = 0; j < picture.height; ++j)  // the picture itself untouched, below the strip
    for (int i = 0; i < picture.width; ++i) ASSERT_EQ(out.pixel(i, j + strip)[0], 200);
  int lit = 0;  // and the text drawn in the strip
  for (int j = 0; j < strip; ++j)
    for (int i = 0; i < out.width; ++i) lit += out.pixel(i, j)[0] > 0;
  EXPECT_GT(lit, 10);
  EXPECT_EQ(above_caption(picture, Caption{}, glm::dvec3(0.0)).height, picture.height);  // nothing asked: as it was
}

TEST(PngOutputs, TransparentAndSixteenBitPngsReadBackToTheirPrecision) {
  test::TempDir dir;
  Image img(5, 3);
  const float values[][4] = {{0, 0, 0, 0},
                             {0.2f, 0.1f, 0.05f, 0.25f},
                             {0.5f, 0.4f, 0.3f, 0.6f},
                             {0.9f, 0.8f, 0.7f, 1},
                             {0.001f, 0, 0.002f, 0.003f}};
  for (int j = 0; j < img.height; ++j)
    for (int i = 0; i < img.width; ++i) std::copy(values[i], values[i] + 4, img.pixel(i, j));
  const glm::dvec3 bg(0.1, 0.2, 0.3);
  for (int bits : {8, 16}) {
    const double step = 1.0 / ((1 << bits) - 1);
    for (const bool transparent : {true, false}) {
      const std::string path = dir.file("p" + std::to_string(bits) + (transparent ? "t" : "o") + ".png");
      write_png(to_display(img, transparent ? std::nullopt : std::optional<glm::dvec3>(bg)), bits, path);
      int read_bits = 0;
      const DisplayImage back = read_png(path, &read_bits);
      EXPECT_EQ(read_bits, bits);
      ASSERT_EQ(back.width, img.width);
      for (int i = 0; i < img.width; ++i) {
        const float* c = img.pixel(i, 1);
        const float* b = back.pixel(i, 1);
        const double a = c[3];
        EXPECT_NEAR(b[3], transparent ? a : 1.0, 0.5 * step + 1e-7) << bits << " " << i;
        for (int k = 0; k < 3; ++k) {
          const double straight = transparent ? (a > 0 ? c[k] / a : 0.0) : c[k] + (1 - a) * bg[k];
          EXPECT_NEAR(b[k], straight, 0.5 * step + 1e-6) << bits << " " << i << " " << k;
          // Premultiplied again, the picture is the render's to the PNG's precision.
          if (transparent) EXPECT_NEAR(b[k] * b[3], c[k], step + 1e-6);
        }
      }
    }
  }
  // The 8-bit picture over a background is the same bytes by either writer.
  write_png(to_rgb8(img, bg), dir.file("rgb8.png"));
  const DisplayImage a = read_png(dir.file("rgb8.png")), b = read_png(dir.file("p8o.png"));
  EXPECT_EQ(a.rgba, b.rgba);

  // A legend on a transparent picture: its bar is opaque, the picture around it stays clear.
  if (default_font().empty()) GTEST_SKIP() << "no font";
  DisplayImage clear = to_display(Image(200, 160), std::nullopt);
  ColorBar bar;
  bar.colors = {{1, 0, 0}, {0, 0, 1}};
  bar.text = glm::dvec3(0.0);
  bar.title = "T";
  draw_color_bar(clear, bar);
  int opaque = 0, clear_pixels = 0;
  for (std::size_t p = 3; p < clear.rgba.size(); p += 4)
    (clear.rgba[p] == 1.0f ? opaque : clear_pixels) += clear.rgba[p] == 1.0f || clear.rgba[p] == 0.0f;
  EXPECT_GT(opaque, 200);          // the bar, at least
  EXPECT_GT(clear_pixels, 20000);  // most of the picture
}

// The legend never covers the picture: it is drawn in a strip beside it, the picture's pixels kept.
TEST(PngOutputs, TheLegendStandsBesideThePicture) {
  if (default_font().empty()) GTEST_SKIP() << "no font";
  Image img(120, 90);
  for (std::size_t p = 0; p < img.rgba.size(); p += 4) img.rgba[p] = img.rgba[p + 3] = 0.5f + 0.4f * (p % 7) / 7;
  ColorBar bar;
  bar.colors = {{1, 0, 0}, {0, 0, 1}};
  bar.title = "temperature";
  const glm::dvec3 page(0.2, 0.3, 0.4);
  const Rgb8Image picture = to_rgb8(img, page), with = beside_legend(picture, bar, page);
  ASSERT_GT(with.width, picture.width);
  EXPECT_EQ(with.height, picture.height);
  int strip_changed = 0;
  for (int j = 0; j < picture.height; ++j) {
    EXPECT_TRUE(std::equal(picture.rgb.begin() + j * picture.width * 3,
                           picture.rgb.begin() + (j + 1) * picture.width * 3, with.rgb.begin() + j * with.width * 3))
        << "row " << j;
    for (int i = picture.width; i < with.width; ++i)
      strip_changed +=
          const_cast<Rgb8Image&>(with).pixel(i, j)[0] != static_cast<unsigned char>(std::lround(0.2 * 255));
  }
  EXPECT_GT(strip_changed, 300);  // the bar and its text are in the strip
  const DisplayImage clear = beside_legend(to_display(img, std::nullopt), bar, std::nullopt);
  EXPECT_EQ(clear.width, with.width);
  EXPECT_EQ(clear.pixel(clear.width - 1, 0)[3], 0.0f);  // the strip is clear where nothing is drawn
  // A horizontal bar stands below the picture: its rows untouched, the bar and text in the strip.
  bar.horizontal = true;
  const Rgb8Image below = beside_legend(picture, bar, page);
  ASSERT_EQ(below.width, picture.width);
  ASSERT_GT(below.height, picture.height);
  EXPECT_TRUE(std::equal(picture.rgb.begin(), picture.rgb.end(), below.rgb.begin()));
  int below_changed = 0;
  for (int j = picture.height; j < below.height; ++j)
    for (int i = 0; i < below.width; ++i)
      below_changed +=
          const_cast<Rgb8Image&>(below).pixel(i, j)[0] != static_cast<unsigned char>(std::lround(0.2 * 255));
  EXPECT_GT(below_changed, 300);
}

}  // namespace
}  // namespace cellproj

namespace cellproj {
namespace {

// --range (clim): the colour map spans the given range instead of the field's, values beyond take
// its ends' colours, the legend shows the range; a bad range names the setting.
TEST(QuickLook, ARangeStretchesTheColourMapOverItAndTheLegendShowsIt) {
  const test::TempDir dir;
  LoadedMesh loaded;
  loaded.mesh = generate("box-tets", 4);
  loaded.mesh.source = "box";
  QuickLook look;
  look.range = std::make_pair(0.25, 0.5);
  const Scene scene = scene_from_json(quick_scene(loaded, dir.file("m.vtu"), {}, look), "box", dir.file(""));
  const PreparedScene p = prepare_scene(scene, loaded);
  const TransferFunction map(colormap("Cool to Warm", 0.25, 0.5), {{0.0, 0.0}});
  for (double s : {0.25, 0.3, 0.4, 0.5}) {
    const glm::dvec3 got = p.tf.color(s), want = map.color(s);
    EXPECT_NEAR(glm::length(got - want), 0.0, 1e-12) << s;
  }
  EXPECT_EQ(p.tf.color(0.0), p.tf.color(0.25));  // below the range: its low end's colour
  EXPECT_EQ(p.tf.color(1.0), p.tf.color(0.5));
  const ColorBar bar = color_bar(p, glm::dvec3(0.0));
  EXPECT_EQ(bar.lo, 0.25);
  EXPECT_EQ(bar.hi, 0.5);
  look.range = std::make_pair(0.5, 0.25);
  try {
    quick_scene(loaded, dir.file("m.vtu"), {}, look);
    FAIL() << "a range from high to low was taken";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("setting 'range'"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace cellproj
