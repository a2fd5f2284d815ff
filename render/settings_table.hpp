#pragma once
// The render settings, each declared once, as pbrt-v4 and Open VKL declare a parameter where it is
// read: one row per setting gives its name, what it takes, which renderers read it, its help, how
// its text is read into RenderSettings and how it is printed back (its default is what a default
// RenderSettings prints). The command line's options, the scene files' keys, the Python keywords,
// the C API's names, the refusal of a setting a renderer does not read and --stats' echo are all
// made from this table (docs/architecture.md, "Adding a setting").
//
// The library names a setting in its messages as `setting 'backend'` (setting_word); each front
// end spells that in its own syntax (--backend, backend=, "backend") with spell_settings.
#include <string>
#include <utility>
#include <vector>

#include "render/renderer.hpp"
#include "render/settings.hpp"

namespace cellproj {

struct SettingRow {
  const char* name;  // "table-size"; scene files and Python also take "table_size"
  const char* help;  // what it does, for help texts (its choices and default are added by setting_help)
  bool repeatable;   // each use adds one ("iso"); the others take the last use
  // Whether the renderer made from `s` reads this setting; a front end refuses it otherwise.
  bool (*reads)(const RenderSettings& s);
  // Sets it from `text` (a repeatable one: adds one); InputError for a bad value, without the name.
  void (*set)(RenderSettings& s, const std::string& text);
  // Its value in `s` as the text `set` takes back ("" for an empty list); of a default
  // RenderSettings, its default.
  std::string (*print)(const RenderSettings& s);
  // What it takes: its choices ("auto, on, off") or a description ("an integer in [2, 8192]").
  std::string (*takes)();
};

// Every render setting, "method" first (rows are applied in this order).
const std::vector<SettingRow>& render_settings();
// The row of `name` ("table-size" or "table_size"); nullptr when there is none.
const SettingRow* find_setting(const std::string& name);
// "setting 'backend'": how library messages name a setting, for front ends to spell (below).
std::string setting_word(const std::string& name);
// The row's help with what it takes and its default: "... (auto, on, off; default auto)".
std::string setting_help(const SettingRow& row);

// Every `setting 'NAME'` of a library message spelled as a front end says it: before + NAME +
// after, with '-' as `dash` ("--" "" '-' gives the CLI's option; "" "=" '_' gives table_size=).
std::string spell_settings(const std::string& message, const std::string& before, const std::string& after,
                           char dash = '-');

// The settings as a user gives them: by name, as text, in the order given.
struct RenderOptions {
  std::vector<std::pair<std::string, std::string>> words;  // (row name, text); a repeatable row once per use
  std::vector<std::string> given;                          // the names the user gave (scene defaults are not)
};

// Sets setting `name` (either spelling) from `text`, checked now on its own: InputError naming the
// setting for a bad value, or for an unknown name (listing the known ones). A non-repeatable
// setting given again replaces its text.
void set_option(RenderOptions& options, const std::string& name, const std::string& text);
// The text of setting `name`: the last given, or its default.
std::string option_text(const RenderOptions& options, const std::string& name);
bool option_given(const RenderOptions& options, const std::string& name);

// The settings: the defaults, each given row applied in the table's order, then the checks of
// settings that go together (the layers' one iso-value); InputError naming the setting.
RenderSettings settings_from(const RenderOptions& options);

// InputError when `given` names a setting that the renderer of `settings` does not read
// ("setting 'sort' does not apply to setting 'method' exact, which reads setting 'method', ...").
void refuse_unused(const RenderSettings& settings, const std::vector<std::string>& given);

// The settings the renderer of `settings` reads, each with its value as text (--stats' echo).
std::vector<std::pair<std::string, std::string>> settings_read(const RenderSettings& settings);

// "1,2,3": the comma-separated numbers of setting `name`; InputError naming it for an item that
// is not one.
std::vector<int> parse_int_list(const std::string& name, const std::string& text);
std::vector<double> parse_number_list(const std::string& name, const std::string& text);

}  // namespace cellproj
