#include "render/names.hpp"

#include <array>

#include "base/error.hpp"
#include "base/name_table.hpp"

namespace cellproj {
namespace {

// The projection methods' names are their traits' (projection/method.hpp).
template <std::size_t... I>
constexpr std::array<std::pair<ProjectionMethod, const char*>, sizeof...(I)> method_table(std::index_sequence<I...>) {
  return {{{kProjectionMethods[I].method, kProjectionMethods[I].name}...}};
}
constexpr auto kMethods = method_table(std::make_index_sequence<std::size(kProjectionMethods)>());
constexpr std::pair<Backend, const char*> kBackends[] = {
    {Backend::software, "software"},
    {Backend::opengl, "opengl"},
    {Backend::opengl_8bit, "opengl-8bit"},
    {Backend::opengl_8bit_dithered, "opengl-8bit-dither"},
};
constexpr std::pair<SortMethod, const char*> kSorts[] = {{SortMethod::automatic, "auto"},
                                                         {SortMethod::centroid, "centroid"},
                                                         {SortMethod::mpvo, "mpvo"},
                                                         {SortMethod::mpvo_abuffer, "mpvo-abuffer"},
                                                         {SortMethod::pairwise, "pairwise"}};
constexpr std::pair<GapMethod, const char*> kGaps[] = {
    {GapMethod::automatic, "auto"}, {GapMethod::overlaps, "overlaps"}, {GapMethod::abuffer, "abuffer"}};
constexpr std::pair<Tetrahedralize, const char*> kModes[] = {
    {Tetrahedralize::problem, "problem"}, {Tetrahedralize::all, "all"}, {Tetrahedralize::none, "none"}};
constexpr std::pair<CellInterpolation, const char*> kInterpolations[] = {
    {CellInterpolation::isoparametric, "isoparametric"}, {CellInterpolation::canonical_tets, "canonical-tets"}};
constexpr std::pair<SliceAxis, const char*> kSliceAxes[] = {{SliceAxis::automatic, "auto"},
                                                            {SliceAxis::view, "view"},
                                                            {SliceAxis::x, "x"},
                                                            {SliceAxis::y, "y"},
                                                            {SliceAxis::z, "z"}};
constexpr std::pair<SliceIntegral, const char*> kSliceIntegrals[] = {{SliceIntegral::sampled, "sampled"},
                                                                     {SliceIntegral::preintegrated, "preintegrated"}};
constexpr std::pair<SampleFilter, const char*> kSampleFilters[] = {{SampleFilter::box, "box"},
                                                                   {SampleFilter::tent, "tent"}};
constexpr std::pair<SmallCells, const char*> kSmallCells[] = {
    {SmallCells::splat, "splat"}, {SmallCells::draw, "draw"}, {SmallCells::skip, "skip"}};
constexpr std::pair<Silhouettes, const char*> kSilhouettes[] = {{Silhouettes::none, "none"},
                                                                {Silhouettes::visible, "visible"},
                                                                {Silhouettes::hidden, "hidden"},
                                                                {Silhouettes::both, "both"}};
constexpr std::pair<IsoMode, const char*> kIsoModes[] = {
    {IsoMode::ordered, "ordered"}, {IsoMode::blend2, "blend2"}, {IsoMode::oit3, "oit3"}, {IsoMode::oit4, "oit4"}};
constexpr std::pair<IsoOpacity, const char*> kIsoOpacities[] = {
    {IsoOpacity::constant, "constant"}, {IsoOpacity::spectrum, "spectrum"}, {IsoOpacity::spectrum_fit, "spectrum-fit"}};

}  // namespace

ProjectionMethod parse_projection_method(const std::string& n) { return from_name(kMethods, n, "projection method"); }
std::string projection_method_names() { return names(kMethods); }

Backend parse_backend(const std::string& n) { return from_name(kBackends, n, "back end"); }
const char* name_of(Backend backend) { return name_in(kBackends, backend); }
std::string backend_names() { return names(kBackends); }

SortMethod parse_sort_method(const std::string& n) { return from_name(kSorts, n, "sort"); }
const char* name_of(SortMethod method) { return name_in(kSorts, method); }
std::string sort_method_names() { return names(kSorts); }

GapMethod parse_gap_method(const std::string& n) { return from_name(kGaps, n, "gap method"); }
const char* name_of(GapMethod method) { return name_in(kGaps, method); }
std::string gap_method_names() { return names(kGaps); }

Tetrahedralize parse_tetrahedralize(const std::string& n) { return from_name(kModes, n, "tetrahedralize mode"); }
const char* name_of(Tetrahedralize mode) { return name_in(kModes, mode); }
std::string tetrahedralize_names() { return names(kModes); }

CellInterpolation parse_cell_interpolation(const std::string& n) {
  return from_name(kInterpolations, n, "cell interpolation");
}
const char* name_of(CellInterpolation interpolation) { return name_in(kInterpolations, interpolation); }
std::string cell_interpolation_names() { return names(kInterpolations); }

SliceAxis parse_slice_axis(const std::string& n) { return from_name(kSliceAxes, n, "slice axis"); }
const char* name_of(SliceAxis axis) { return name_in(kSliceAxes, axis); }
std::string slice_axis_names() { return names(kSliceAxes); }

SliceIntegral parse_slice_integral(const std::string& n) { return from_name(kSliceIntegrals, n, "slice integral"); }
const char* name_of(SliceIntegral integral) { return name_in(kSliceIntegrals, integral); }
std::string slice_integral_names() { return names(kSliceIntegrals); }

SampleFilter parse_sample_filter(const std::string& n) { return from_name(kSampleFilters, n, "sample filter"); }
const char* name_of(SampleFilter filter) { return name_in(kSampleFilters, filter); }
std::string sample_filter_names() { return names(kSampleFilters); }

SmallCells parse_small_cells(const std::string& n) { return from_name(kSmallCells, n, "small-cells mode"); }
const char* name_of(SmallCells mode) { return name_in(kSmallCells, mode); }
std::string small_cells_names() { return names(kSmallCells); }

Silhouettes parse_silhouettes(const std::string& n) { return from_name(kSilhouettes, n, "silhouettes mode"); }
const char* name_of(Silhouettes mode) { return name_in(kSilhouettes, mode); }
std::string silhouettes_names() { return names(kSilhouettes); }

IsoMode parse_iso_mode(const std::string& n) { return from_name(kIsoModes, n, "iso-surface mode"); }
const char* name_of(IsoMode mode) { return name_in(kIsoModes, mode); }
std::string iso_mode_names() { return names(kIsoModes); }

IsoOpacity parse_iso_opacity(const std::string& n) { return from_name(kIsoOpacities, n, "iso-surface opacity model"); }
const char* name_of(IsoOpacity model) { return name_in(kIsoOpacities, model); }
std::string iso_opacity_names() { return names(kIsoOpacities); }

void parse_render_method(const std::string& name, RenderSettings& settings) {
  for (const auto& [reduction, n] : {std::pair{RayReduction::maximum, "mip"}, std::pair{RayReduction::minimum, "minip"},
                                     std::pair{RayReduction::average, "average"}})
    if (name == n) {
      settings.mode = RenderMode::reduction;
      settings.reduction = reduction;
      return;
    }
  if (name == "layers") {
    settings.mode = RenderMode::layers;
    return;
  }
  if (name == "exact" || name == "slicing") {
    settings.mode = name == "exact" ? RenderMode::exact : RenderMode::slicing;
    return;
  }
  for (const auto& [method, n] : kMethods)
    if (name == n) {
      settings.mode = RenderMode::projection;
      settings.projection.method = method;
      return;
    }
  throw InputError("unknown method '" + name + "' (known: " + render_method_names() + ")");
}

std::string render_method_name(const RenderSettings& s) {
  switch (s.mode) {
    case RenderMode::projection: return traits(s.projection.method).name;
    case RenderMode::exact: return "exact";
    case RenderMode::slicing: return "slicing";
    case RenderMode::layers: return "layers";
    case RenderMode::reduction:
      return s.reduction == RayReduction::maximum ? "mip" : s.reduction == RayReduction::minimum ? "minip" : "average";
  }
  return "?";
}

std::string render_method_names() {
  return "exact, slicing, mip, minip, average, layers, " + projection_method_names();
}

}  // namespace cellproj
