#pragma once
// The names of the render settings' values (render/settings_table.hpp), in every front end and file: for each enum,
// parsing (an InputError listing the known names), printing, and the list for help texts.
#include <string>

#include "render/report.hpp"
#include "render/settings.hpp"

namespace cellproj {

// Each parse_* throws InputError "unknown WHAT 'name' (known: a, b, c)".
ProjectionMethod parse_projection_method(const std::string& name);
std::string projection_method_names();  // name_of(ProjectionMethod) is the method's trait

Backend parse_backend(const std::string& name);
const char* name_of(Backend backend);
std::string backend_names();

SortMethod parse_sort_method(const std::string& name);
const char* name_of(SortMethod method);
std::string sort_method_names();

GapMethod parse_gap_method(const std::string& name);
const char* name_of(GapMethod method);
std::string gap_method_names();

Tetrahedralize parse_tetrahedralize(const std::string& name);
const char* name_of(Tetrahedralize mode);
std::string tetrahedralize_names();

CellInterpolation parse_cell_interpolation(const std::string& name);
const char* name_of(CellInterpolation interpolation);
std::string cell_interpolation_names();

SliceAxis parse_slice_axis(const std::string& name);
const char* name_of(SliceAxis axis);
std::string slice_axis_names();

SliceIntegral parse_slice_integral(const std::string& name);
const char* name_of(SliceIntegral integral);
std::string slice_integral_names();

SampleFilter parse_sample_filter(const std::string& name);
const char* name_of(SampleFilter filter);
std::string sample_filter_names();

SmallCells parse_small_cells(const std::string& name);
const char* name_of(SmallCells mode);
std::string small_cells_names();

Silhouettes parse_silhouettes(const std::string& name);
const char* name_of(Silhouettes mode);
std::string silhouettes_names();

IsoMode parse_iso_mode(const std::string& name);
const char* name_of(IsoMode mode);
std::string iso_mode_names();

IsoOpacity parse_iso_opacity(const std::string& name);
const char* name_of(IsoOpacity model);
std::string iso_opacity_names();

// "exact", "slicing" or a projection method's name into settings.mode (and settings.projection.method).
void parse_render_method(const std::string& name, RenderSettings& settings);
std::string render_method_names();                               // "exact, slicing, pt-linear, ..."
std::string render_method_name(const RenderSettings& settings);  // what parse_render_method read

}  // namespace cellproj
