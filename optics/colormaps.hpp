#pragma once
// Colour maps built in by name, so that a first picture needs no preset file: ParaView's default
// ("Cool to Warm"), matplotlib's perceptual maps under ParaView's names, and a few classics.
// The perceptual maps are sampled at 17 evenly spaced points and interpolated linearly in RGB
// (at most 0.03 from the continuous map on any channel); few points keep pt-breakpoints fast,
// since every colour point is a breakpoint of the transfer function.
#include <string>
#include <vector>

#include "optics/transfer_function.hpp"

namespace cellproj {

// The map's colour points stretched over [lo, hi]. `name` is ParaView's ("Viridis (matplotlib)")
// or the short alias ("viridis"), case-insensitively; InputError listing the names otherwise.
std::vector<ColorPoint> colormap(const std::string& name, double lo, double hi);
// "Cool to Warm (coolwarm), Viridis (matplotlib) (viridis), ...": for help texts and errors.
std::string colormap_names();
std::vector<std::string> colormap_list();  // ParaView's names

}  // namespace cellproj
