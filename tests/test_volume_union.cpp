// Several volumes in one picture (issue 19): meshes that only touch give the picture of their
// union, overlapping meshes add their extinctions and emissions, the order-independent modes are
// independent of the volumes' order and the threads, the scene's "volumes" list and its errors.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include <tbb/task_arena.h>
#include <nlohmann/json.hpp>

#include "base/error.hpp"
#include "mesh/generate.hpp"
#include "raycast/volume_union.hpp"
#include "render/volume_set.hpp"
#include "scene/scene_file.hpp"
#include "tests/test_util.hpp"

namespace cellproj {
namespace {

// The cells of m whose first point lies on one side of x = 0 (all points kept: the same recentring).
Mesh half(const Mesh& m, bool left) {
  Mesh h = m;
  h.connectivity.clear(), h.offsets = {0}, h.types.clear();
  const MeshView v = m.view();
  for (std::int64_t c = 0; c < m.n_cells(); ++c) {
    glm::dvec3 centre(0.0);
    const std::int64_t n = m.offsets[c + 1] - m.offsets[c];
    for (std::int64_t k = 0; k < n; ++k) centre += v.point(m.connectivity[m.offsets[c] + k]);
    if ((centre.x < 0) == left) h.add_cell(static_cast<CellType>(m.types[c]), &m.connectivity[m.offsets[c]]);
  }
  return h;
}

// s = 0.5 + 0.2 x + 0.15 y - 0.1 z: linear, so every canonical tetrahedron holds it exactly.
void set_linear_field(Mesh& m) {
  const MeshView v = m.view();
  m.fields.clear();
  PointField& f = m.add_field("s", "linear");
  for (std::int64_t p = 0; p < m.n_points(); ++p) {
    const glm::dvec3 x = v.point(p);
    f.values[p] = 0.5 + 0.2 * x.x + 0.15 * x.y - 0.1 * x.z;
  }
}

double max_difference(const Image& a, const Image& b) { return compare(a, b).max_abs; }

Image union_of(const std::vector<const Mesh*>& meshes, const std::vector<const TransferFunction*>& tfs,
               const Camera& camera, int n, IsoStats* stats = nullptr, IsoMode mode = IsoMode::ordered,
               const std::vector<std::vector<IsoSurface>>& surfaces = {}) {
  std::vector<std::unique_ptr<CellRayTracer>> tracers;
  std::vector<VolumePart> parts;
  for (std::size_t k = 0; k < meshes.size(); ++k) {
    tracers.push_back(std::make_unique<CellRayTracer>(meshes[k]->view()));
    parts.push_back({tracers.back().get(), test::field_values(*meshes[k]), meshes[k]->n_points(), tfs[k],
                     surfaces.empty() ? std::vector<IsoSurface>{} : surfaces[k], true});
  }
  return render_volume_union(parts, mode, IsoOpacity::constant, camera, n, n, stats);
}

TEST(VolumeUnion, TwoHalvesOfAMeshGiveTheWholeMeshsPicture) {
  // Cells of one mesh split between two volumes touch on a surface and never overlap: the picture
  // is the exact renderer's of the whole mesh (field linear in each canonical tetrahedron).
  Mesh m = test::twisted_mixed(5);
  PointField& f = m.add_field("s", "smooth");
  for (std::int64_t p = 0; p < m.n_points(); ++p) {
    const glm::dvec3 x = m.view().point(p);
    f.values[p] = std::sin(2 * x.x) * x.y + x.z * x.z;
  }
  const Mesh left = half(m, true), right = half(m, false);
  ASSERT_GT(left.n_cells(), 0);
  ASSERT_GT(right.n_cells(), 0);
  const TransferFunction tf({{-1, {0.1, 0.2, 0.9}}, {0.2, {0.9, 0.8, 0.2}}, {1, {1, 0.1, 0.1}}},
                            {{-1, 0.3}, {0.4, 3.0}, {1, 1.0}});
  for (const Camera& c : test::views_of_unit_mesh(3)) {
    IsoStats st;
    const Image both = union_of({&left, &right}, {&tf, &tf}, c, 40, &st);
    const Image whole = test::exact(m, "", tf, c, 40, 40, CellInterpolation::canonical_tets);
    EXPECT_LT(max_difference(both, whole), 1e-6);
    EXPECT_EQ(st.overlap_pieces, 0);
  }
}

TEST(VolumeUnion, OverlappingVolumesAddTheirExtinctionsAndEmissions) {
  // Two meshes of the same cube, different cells, one linear field: with constant extinctions k1,
  // k2 and colours C1(s), C2(s) the overlap is one medium of extinction k1 + k2 and colour
  // (k1 C1 + k2 C2) / (k1 + k2), again linear in s (Max 1995 section 4: absorption and emission add).
  Mesh tets = generate("box-tets", 4), hexes = generate("box", 3);
  set_linear_field(tets);
  set_linear_field(hexes);
  const glm::dvec3 a0(1, 0, 0), a1(0, 1, 0), b0(0, 0, 1), b1(1, 1, 0);
  const double k1 = 1.2, k2 = 0.7;
  const TransferFunction tf1({{0, a0}, {1, a1}}, {{0, k1}}), tf2({{0, b0}, {1, b1}}, {{0, k2}});
  const TransferFunction sum({{0, (k1 * a0 + k2 * b0) / (k1 + k2)}, {1, (k1 * a1 + k2 * b1) / (k1 + k2)}},
                             {{0, k1 + k2}});
  for (const Camera& c : test::views_of_unit_mesh(3)) {
    IsoStats st;
    const Image both = union_of({&tets, &hexes}, {&tf1, &tf2}, c, 32, &st);
    const Image one = test::exact(tets, "", sum, c, 32, 32, CellInterpolation::canonical_tets);
    EXPECT_LT(max_difference(both, one), 1e-6);
    EXPECT_GT(st.overlap_pieces, 0);
  }
}

TEST(VolumeUnion, OrderIndependentModesDoNotDependOnTheVolumesOrderOrTheThreads) {
  Mesh a = generate("box-tets", 8), b = generate("shells", 6);
  const TransferFunction ta = test::constant_tf(0.4, {0.2, 0.4, 1.0}), tb = test::constant_tf(0.8, {1.0, 0.6, 0.2});
  const std::vector<IsoSurface> sa = {{0.8, {1, 0, 0}, 0.4, true}},
                                sb = {{0.0, {0, 1, 0}, 0.3, true}, {0.5, {1, 1, 0}, 0.5, true}};
  const Camera c = test::views_of_unit_mesh(2)[1];
  for (IsoMode mode : {IsoMode::oit3, IsoMode::oit4}) {
    Image ab, ba, ab1;
    tbb::task_arena(3).execute([&] {
      ab = union_of({&a, &b}, {&ta, &tb}, c, 36, nullptr, mode, {sa, sb});
      ba = union_of({&b, &a}, {&tb, &ta}, c, 36, nullptr, mode, {sb, sa});
    });
    tbb::task_arena(1).execute([&] { ab1 = union_of({&a, &b}, {&ta, &tb}, c, 36, nullptr, mode, {sa, sb}); });
    EXPECT_LT(max_difference(ab, ba), 1e-6);
    EXPECT_EQ(max_difference(ab, ab1), 0.0);
    double light = 0.0;
    for (int j = 0; j < 36; ++j) light += ab.pixel(18, j)[3];
    EXPECT_GT(light, 1.0);  // not an empty picture
  }
}

TEST(VolumeUnion, OnlyTheExactRendererDrawsSeveralVolumes) {
  const Mesh m = generate("box-tets", 2);
  const Volume v(m.view());
  const TransferFunction tf = test::constant_tf(1.0, {1, 1, 1});
  const std::vector<VolumeEntry> entries{{&v, field_of(m, "scalar"), &tf}, {&v, field_of(m, "scalar"), &tf}};
  RenderSettings projection;
  EXPECT_THROW(render_volumes(entries, projection, test::looking_down(3), {8, 8}), InputError);
  RenderSettings exact;
  exact.mode = RenderMode::exact;
  RenderReport report;
  const Image img = render_volumes(entries, exact, test::looking_down(3), {8, 8}, &report);
  EXPECT_GT(img.pixel(4, 4)[3], 0.0f);
}

TEST(VolumeUnion, TheScenesVolumesListAndItsErrors) {
  const nlohmann::json tf = {{"color", {{0, 1, 1, 1}}}, {"extinction", {{0, 1}}}};
  nlohmann::json j = {{"volumes",
                       {{{"mesh", "a.vtu"}, {"transfer_function", tf}},
                        {{"mesh", "b.vtu"},
                         {"field", "p"},
                         {"transfer_function", tf},
                         {"volume", false},
                         {"iso", {{{"value", 0.5}, {"color", {1, 0, 0}}, {"opacity", 0.3}}}}}}},
                      {"iso_mode", "oit4"}};
  const Scene s = scene_from_json(j, "two.json", "/data");
  ASSERT_EQ(s.volumes.size(), 2u);
  EXPECT_EQ(s.volumes[1].mesh, "/data/b.vtu");
  EXPECT_EQ(s.volumes[1].field, "p");
  EXPECT_FALSE(s.volumes[1].volume);
  ASSERT_EQ(s.volumes[1].iso.size(), 1u);
  EXPECT_DOUBLE_EQ(s.volumes[1].iso[0].opacity, 0.3);
  EXPECT_EQ(s.mesh, "/data/a.vtu");  // the first volume's, for what reads one mesh
  // One volume is an ordinary scene, its iso-surfaces the scene's.
  nlohmann::json one = j;
  one["volumes"].erase(0);
  const Scene s1 = scene_from_json(one, "one.json", "/data");
  EXPECT_TRUE(s1.volumes.empty());
  EXPECT_EQ(s1.mesh, "/data/b.vtu");
  EXPECT_EQ(std::count_if(s1.iso_options.begin(), s1.iso_options.end(), [](const auto& o) { return o.first == "iso"; }),
            1);
  const auto refused = [](nlohmann::json bad, const std::string& says) {
    try {
      scene_from_json(bad, "bad.json", "");
      ADD_FAILURE() << "accepted " << bad.dump();
    } catch (const InputError& e) {
      EXPECT_NE(std::string(e.what()).find(says), std::string::npos) << e.what();
    }
  };
  nlohmann::json both = j;
  both["mesh"] = "c.vtu";
  refused(both, "mesh: with a \"volumes\" list, give it inside each volume");
  refused({{"volumes", nlohmann::json::array()}}, "volumes: the list is empty");
  nlohmann::json bad_iso = j;
  bad_iso["volumes"][1]["iso"][0]["opacity"] = 2;
  refused(bad_iso, "volumes[1]");
  nlohmann::json no_tf = j;
  no_tf["volumes"][0].erase("transfer_function");
  refused(no_tf, "volumes[0]: missing \"transfer_function\"");
}

}  // namespace
}  // namespace cellproj
