// The case codec: defaults, unit conversion, refusals with reasons (docs/lbmsim.md 2.6, 2.10).
#include <gtest/gtest.h>

#include <functional>

#include <nlohmann/json.hpp>

#include "core/error.hpp"
#include "lbm/case_json.hpp"
#include "lbm/units.hpp"
#include "lbm/voxelize.hpp"

namespace fest::lbm {
namespace {

using nlohmann::json;

std::string error_of(const json& j) {
  try {
    parse_case(j, "case.json");
  } catch (const Error& e) {
    EXPECT_EQ(e.status(), Status::bad_input);
    return e.what();
  }
  return "";
}

TEST(LbmCase, DefaultsAndTauFromRe) {
  const Case c = parse_case(json::parse(R"({"size":[64,64],"re":100,"u_ref":0.1,"steps":10})"), "x");
  EXPECT_EQ(c.dim, 2);
  EXPECT_EQ(c.lattice, LatticeKind::d2q9);
  EXPECT_NEAR(c.collision.tau, 0.5 + 3 * 0.1 * 64 / 100, 1e-15);
  EXPECT_TRUE(c.periodic(0));
}

TEST(LbmCase, PhysicalUnits) {
  // dx = 1 mm, 1 m/s <-> 0.05: dt = 5e-5 s; nu = 1e-6 m^2/s -> nu_lat = 1e-6 * 5e-5 / 1e-6 = 5e-5.
  const Case c = parse_case(json::parse(R"({"size":[10,10,10],"steps":1,
      "units":{"dx":0.001,"u_phys":1.0,"u_lattice":0.05,"nu_phys":1e-6,"rho_phys":1000}})"), "x");
  EXPECT_NEAR(c.units.dt(), 5e-5, 1e-18);
  EXPECT_NEAR(c.collision.tau, 0.5 + 3 * 5e-5, 1e-12);
  const UnitTable t = unit_table(c, false);
  EXPECT_NEAR(t.re, 0.05 * 10 / 5e-5, 1e-6);
  EXPECT_NEAR(t.pressure_scale, 1000 * 1e-6 / (5e-5 * 5e-5), 1e-6);
}

TEST(LbmCase, UnknownKeyGetsAHint) {
  EXPECT_EQ(error_of(json::parse(R"({"size":[8,8],"colision":{"tau":0.6},"steps":1})")),
            "case key \"colision\" is unknown (did you mean \"collision\"?) (case.json)");
}

TEST(LbmCase, UnstableParametersAreRefusedWithTheReason) {
  EXPECT_NE(error_of(json::parse(R"({"size":[8,8],"collision":{"tau":0.5},"steps":1})")).find("zero viscosity"),
            std::string::npos);
  EXPECT_NE(error_of(json::parse(R"({"size":[8,8],"collision":{"tau":0.6},"u_ref":0.2,"steps":1})")).find("Mach number"),
            std::string::npos);
  EXPECT_NE(error_of(json::parse(R"({"size":[8,8],"collision":{"nu":-1},"steps":1})")).find("nu > 0"), std::string::npos);
  EXPECT_NE(error_of(json::parse(R"({"size":[8,8],"collision":{"tau":0.6,"lambda":0},"steps":1})")).find("lambda"),
            std::string::npos);
}

TEST(LbmCase, EquilibriumAndCurvedWalls) {
  const Case c = parse_case(
      json::parse(R"({"size":[8,8],"collision":{"tau":0.6,"equilibrium":"incompressible"},"curved_walls":"bouzidi","steps":1})"),
      "x");
  EXPECT_TRUE(c.collision.incompressible);
  EXPECT_TRUE(c.bouzidi);
  const json back = case_to_json(c);
  EXPECT_EQ(back["collision"]["equilibrium"], "incompressible");
  EXPECT_EQ(back["curved_walls"], "bouzidi");
  EXPECT_FALSE(parse_case(json::parse(R"({"size":[8,8],"collision":{"tau":0.6},"steps":1})"), "x").collision.incompressible);
  EXPECT_EQ(error_of(json::parse(R"({"size":[8,8],"collision":{"tau":0.6,"equilibrium":"weak"},"steps":1})")),
            "case key \"collision.equilibrium\" = \"weak\" must be compressible or incompressible (case.json)");
  EXPECT_NE(error_of(json::parse(R"({"size":[8,8],"collision":{"tau":0.6,"equilibrum":"incompressible"},"steps":1})"))
                .find("did you mean \"collision.equilibrium\""),
            std::string::npos);
}

TEST(LbmCase, InconsistentFacesAndSizes) {
  EXPECT_NE(error_of(json::parse(R"({"size":[8,8],"collision":{"tau":0.6},"faces":{"x-":"wall"},"steps":1})"))
                .find("periodic face needs a periodic opposite"),
            std::string::npos);
  EXPECT_NE(error_of(json::parse(R"({"size":[8],"collision":{"tau":0.6},"steps":1})")).find("size"), std::string::npos);
  EXPECT_NE(error_of(json::parse(R"({"size":[8,2],"collision":{"tau":0.6},"steps":1})")).find("outside"), std::string::npos);
}

TEST(LbmCase, Overrides) {
  json doc = json::parse(R"({"size":[8,8],"collision":{"tau":0.6},"steps":1})");
  apply_override(doc, "collision.tau=0.7");
  apply_override(doc, "collision.model=trt");
  const Case c = parse_case(doc, "x");
  EXPECT_EQ(c.collision.tau, 0.7);
  EXPECT_EQ(c.collision.model, CollisionModel::trt);
  EXPECT_THROW(apply_override(doc, "novalue"), Error);
}

// Overrides speak the case's terms (a tool puts its flag before the message): the text
// comes first, quoted, and no flag is named.
TEST(LbmCase, OverrideErrorsNameNoFlag) {
  auto message = [](const std::function<void()>& f) {
    try {
      f();
    } catch (const Error& e) {
      EXPECT_EQ(e.status(), Status::usage);
      return std::string(e.what());
    }
    ADD_FAILURE() << "no error";
    return std::string();
  };
  EXPECT_EQ(message([] { parse_override("novalue"); }), "\"novalue\" must be key=value");
  EXPECT_EQ(message([] { parse_override("=1"); }), "\"=1\" must be key=value");
  EXPECT_EQ(message([] { parse_override("a..b=1"); }), "\"a..b=1\": empty key part");
  const CaseOverride o = parse_override("collision.tau=0.7=x");
  EXPECT_EQ(o.path, (std::vector<std::string>{"collision", "tau"}));
  EXPECT_EQ(o.value, "0.7=x");
  json doc = json::parse(R"({"size":[8,8]})");
  EXPECT_EQ(message([&] { apply_override(doc, parse_override("size.x=3")); }), "\"size\" is not an object");
  json list = json::parse("[1, 2]");
  EXPECT_EQ(message([&] { apply_override(list, parse_override("a=1")); }), "the case is not a JSON object");
  apply_override(doc, parse_override("output.fields=[\"speed\"]"));
  EXPECT_EQ(doc["output"]["fields"], json::parse(R"(["speed"])"));
}

TEST(LbmVoxelize, CubeVolumeAndOpenMesh) {
  TriangleSoup cube;
  for (int i = 0; i < 8; ++i) cube.vertices.push_back({double(i & 1), double((i >> 1) & 1), double((i >> 2) & 1)});
  const int f[12][3] = {{0, 2, 1}, {1, 2, 3}, {4, 5, 6}, {5, 7, 6}, {0, 1, 4}, {1, 5, 4},
                        {2, 6, 3}, {3, 6, 7}, {0, 4, 2}, {2, 4, 6}, {1, 3, 5}, {3, 7, 5}};
  for (const auto& t : f) cube.triangles.push_back({t[0], t[1], t[2]});
  EXPECT_EQ(count_open_edges(cube).boundary, 0u);
  // Unit cube scaled to 8 cells inside a 12^3 lattice with margin 2: 8^3 nodes.
  Flags flags;
  flags.size = {12, 12, 12};
  flags.id.assign(12 * 12 * 12, 0);
  VoxelizeOptions o;
  o.margin = 2;
  EXPECT_EQ(voxelize(cube, o, flags), 512u);
  cube.triangles.pop_back();
  EXPECT_EQ(count_open_edges(cube).boundary, 3u);
}

}  // namespace
}  // namespace fest::lbm
