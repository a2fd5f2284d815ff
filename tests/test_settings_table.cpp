// The one table of render settings (render/settings_table.hpp): every front end's names, checks,
// refusals and echo come from its rows, so the rows themselves are checked here.
#include <gtest/gtest.h>

#include <regex>
#include <set>

#include "base/error.hpp"
#include "render/names.hpp"
#include "render/settings_table.hpp"

using namespace cellproj;

namespace {

// Every setting's value as printed, the whole RenderSettings read through the table.
std::vector<std::string> printed(const RenderSettings& s) {
  std::vector<std::string> out;
  for (const SettingRow& row : render_settings()) out.push_back(row.print(s));
  return out;
}

RenderSettings with(std::initializer_list<std::pair<const char*, const char*>> words) {
  RenderOptions o;
  for (const auto& [name, text] : words) set_option(o, name, text);
  return settings_from(o);
}

}  // namespace

TEST(SettingsTable, NamesAreUniqueLowerCaseWordsAndMethodComesFirst) {
  std::set<std::string> seen;
  for (const SettingRow& row : render_settings()) {
    EXPECT_TRUE(std::regex_match(row.name, std::regex("[a-z][a-z0-9-]*"))) << row.name;
    EXPECT_TRUE(seen.insert(row.name).second) << row.name << " twice";
    EXPECT_FALSE(std::string(row.help).empty()) << row.name;
    EXPECT_EQ(find_setting(row.name), &row);
  }
  EXPECT_STREQ(render_settings().front().name, "method");
  EXPECT_EQ(find_setting("table_size"), find_setting("table-size"));
  EXPECT_EQ(find_setting("colour"), nullptr);
}

// A default printed and set again changes nothing: the default is written once, in the settings'
// structs, and every front end's default text is read from there.
TEST(SettingsTable, EveryDefaultPrintsAndReadsBackToItself) {
  const RenderSettings defaults;
  for (const SettingRow& row : render_settings()) {
    const std::string text = row.print(defaults);
    if (text.empty() || text == "nan") continue;  // nothing given (no iso-surface), or "the method's default"
    RenderSettings s;
    row.set(s, text);
    EXPECT_EQ(printed(s), printed(defaults)) << row.name << " " << text;
  }
  EXPECT_EQ(option_text({}, "table-size"), "256");
  EXPECT_EQ(option_text({}, "method"), "pt-breakpoints");
}

TEST(SettingsTable, ValuesPrintAsTheyWereGiven) {
  const RenderSettings s = with({{"method", "slicing"},
                                 {"slices", "64"},
                                 {"slice_axis", "view"},
                                 {"backend", "opengl"},
                                 {"splat-threshold", "2.5"}});
  EXPECT_EQ(s.mode, RenderMode::slicing);
  EXPECT_EQ(s.slicing.backend, Backend::opengl);  // one setting, both renderers' fields
  EXPECT_EQ(s.projection.backend, Backend::opengl);
  EXPECT_EQ(s.slicing.splat.threshold, 2.5);
  std::vector<std::pair<std::string, std::string>> echo = settings_read(s);
  const auto value = [&](const std::string& name) {
    for (const auto& [n, v] : echo)
      if (n == name) return v;
    return std::string("(not read)");
  };
  EXPECT_EQ(value("slices"), "64");
  EXPECT_EQ(value("slice-axis"), "view");
  EXPECT_EQ(value("splat-threshold"), "2.5");
  EXPECT_EQ(value("sort"), "(not read)");  // slicing sorts nothing
  const RenderSettings iso = with({{"method", "exact"}, {"iso", "0.5:1,0,0,0.25"}, {"iso", "0.8"}});
  EXPECT_EQ(find_setting("iso")->print(iso), "0.5:1,0,0,0.25 0.8");
}

TEST(SettingsTable, ASettingTheMethodDoesNotReadIsRefusedNamingWhatItReads) {
  for (const SettingRow& row : render_settings())
    for (const char* method : {"pt-linear", "pt-breakpoints", "exact", "slicing", "mip", "layers"}) {
      RenderSettings s = with({{"method", method}, {"iso", "0.5"}});
      if (row.reads(s)) {
        EXPECT_NO_THROW(refuse_unused(s, {row.name})) << row.name << " " << method;
        continue;
      }
      try {
        refuse_unused(s, {row.name});
        ADD_FAILURE() << row.name << " with " << method << " was not refused";
      } catch (const InputError& e) {
        const std::string m = e.what();
        EXPECT_EQ(m.find("setting '" + std::string(row.name) + "' does not apply to setting 'method' " + method +
                         ", which reads setting 'method'"),
                  0u)
            << m;
      }
    }
  // whole-cells is read only by the Gouraud rungs (the exact rungs always draw layers).
  EXPECT_TRUE(find_setting("whole-cells")->reads(with({{"method", "pt-table"}})));
  EXPECT_FALSE(find_setting("whole-cells")->reads(with({{"method", "pt-breakpoints"}})));
}

TEST(SettingsTable, BadValuesNameTheSettingAndAreKeptOut) {
  const std::vector<std::pair<const char*, const char*>> bad = {
      {"table-size", "1"},        {"tile-rows", "-3"},    {"compositing", "fast"}, {"early-termination", "maybe"},
      {"whole-cells", "quads"},   {"sort", "bogus"},      {"slices", "12x"},       {"iso", "0.5:1,0"},
      {"splat-threshold", "nan"}, {"method", "raytrace"}, {"layer", "1,x"}};
  for (const auto& [name, text] : bad) {
    RenderOptions o;
    try {
      set_option(o, name, text);
      ADD_FAILURE() << name << " " << text << " was taken";
    } catch (const InputError& e) {
      EXPECT_EQ(std::string(e.what()).find("setting '" + std::string(name) + "': "), 0u) << e.what();
    }
    EXPECT_TRUE(o.words.empty());
  }
  // Settings that only go together are checked together.
  RenderOptions layers;
  set_option(layers, "method", "layers");
  EXPECT_THROW(settings_from(layers), InputError);  // needs one iso-value
  set_option(layers, "iso", "0.5:1,0,0,0.5");
  EXPECT_THROW(settings_from(layers), InputError);  // layers are opaque
}

TEST(SettingsTable, FrontEndsSpellTheLibrarysWords) {
  const std::string m = "setting 'sort' does not apply to setting 'method' exact, which reads setting 'table-size'";
  EXPECT_EQ(spell_settings(m, "--", ""), "--sort does not apply to --method exact, which reads --table-size");
  EXPECT_EQ(spell_settings(m, "", "=", '_'), "sort= does not apply to method= exact, which reads table_size=");
  EXPECT_EQ(spell_settings("no setting here", "--", ""), "no setting here");
}

TEST(SettingsTable, HelpCarriesTheChoicesAndTheDefault) {
  EXPECT_NE(setting_help(*find_setting("tile-orders")).find("(auto, on, off; default auto)"), std::string::npos);
  EXPECT_NE(setting_help(*find_setting("table-size")).find("default 256)"), std::string::npos);
  EXPECT_NE(setting_help(*find_setting("sort")).find(sort_method_names()), std::string::npos);
}
