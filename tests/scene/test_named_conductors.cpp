// Named conductors (`material` of conductor / roughconductor) against Mitsuba 3's RGB variants.
//
// Reference values: the pip package mitsuba 3.9.1, variant scalar_rgb,
//   mi.traverse(mi.load_dict({'type': 'conductor', 'material': NAME}))['eta.value'] (and 'k.value';
//   roughconductor gives the same), printed with 9 significant digits, which give back the float:
// the table must match them exactly.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <iterator>
#include <string>
#include <vector>

#include "scene/named_conductors.h"
#include "scene/scene_test_files.h"
#include "scene/spd_file.h"
#include "util/error.h"

namespace gdr {
namespace {

namespace fs = std::filesystem;

void expect_same(const ComplexIor& a, const ComplexIor& b, const std::string& what) {
  for (int i = 0; i < 3; ++i) {
    EXPECT_EQ(a.eta[i], b.eta[i]) << what << " eta " << i;
    EXPECT_EQ(a.k[i], b.k[i]) << what << " k " << i;
  }
}

ComplexIor lookup(const std::string& name) {
  ComplexIor ior{};
  EXPECT_TRUE(named_conductor(name, &ior)) << name;
  return ior;
}

struct Reference {
  const char* name;
  ComplexIor ior;
};

const Reference kMitsuba[] = {
    {"Au", {{0.143035978f, 0.375307083f, 1.44204533f}, {3.98299694f, 2.38555646f, 1.60335922f}}},
    {"Cu", {{0.201005474f, 0.923749506f, 1.10221541f}, {3.91326213f, 2.45304513f, 2.14208984f}}},
    // Another measurement than "Cu": not the same values.
    {"Cu_palik", {{0.213228509f, 0.919715405f, 1.10241079f}, {3.92187333f, 2.45733166f, 2.13658404f}}},
    {"Al", {{1.65750086f, 0.880404711f, 0.521244466f}, {9.22381115f, 6.26950216f, 4.83700418f}}},
    // Red outside the gamut in both, clamped to 0 by Mitsuba.
    {"AlSb", {{0.0f, 4.13937473f, 4.6692543f}, {0.0f, 0.094009079f, 1.30057001f}}},
    {"none", {{0.0f, 0.0f, 0.0f}, {1.0f, 1.0f, 1.0f}}},
};

TEST(NamedConductors, AgreeWithMitsuba) {
  for (const Reference& r : kMitsuba) expect_same(lookup(r.name), r.ior, r.name);
}

TEST(NamedConductors, MitsubasNamesExactly) {
  // Mitsuba 3.9.1's data/ior folder (each NAME.eta.spd with NAME.k.spd) and "none".
  const char* names[] = {
      "none", "Ag", "Al", "AlAs", "AlAs_palik", "AlSb", "AlSb_palik", "Au", "Be", "Be_palik", "Cr", "CsI",
      "CsI_palik", "Cu", "Cu2O", "Cu2O_palik", "CuO", "CuO_palik", "Cu_palik", "Hg", "HgTe", "HgTe_palik",
      "Hg_palik", "Ir", "Ir_palik", "K", "K_palik", "Li", "Li_palik", "MgO", "MgO_palik", "Mo", "Mo_palik",
      "Na_palik", "Nb", "Nb_palik", "Ni_palik", "Rh", "Rh_palik", "Se", "Se-e", "Se-e_palik", "Se_palik",
      "SiC", "SiC_palik", "SnTe", "SnTe_palik", "Ta", "Ta_palik", "Te", "Te-e", "Te-e_palik", "Te_palik",
      "ThF4", "ThF4_palik", "TiC", "TiC_palik", "TiN", "TiN_palik", "TiO2", "TiO2-e", "TiO2-e_palik",
      "TiO2_palik", "V_palik", "VC", "VC_palik", "VN", "VN_palik", "W", "a-C", "d-C", "d-C_palik"};
  std::string list = named_conductor_list();
  for (const char* n : names) {
    ComplexIor ior{};
    EXPECT_TRUE(named_conductor(n, &ior)) << n;
    EXPECT_NE(list.find(n), std::string::npos) << n;
  }
  EXPECT_EQ(std::count(list.begin(), list.end(), ',') + 1, static_cast<long>(std::size(names))) << list;
  // Names Mitsuba has no data for are unknown there, and here.
  for (const char* n : {"Na", "Ni", "V", "Au_palik", "au", "Gold", ""}) {
    ComplexIor ior{};
    EXPECT_FALSE(named_conductor(n, &ior)) << n;
  }
}

// Mitsuba's data/ior folder when one is at hand: $GDR_MITSUBA_IOR_DIR, or the pip package in the
// venv of scripts/mitsuba-reference ($GDR_MITSUBA_VENV, default build/venv-mitsuba).
std::string mitsuba_ior_dir() {
  if (const char* d = std::getenv("GDR_MITSUBA_IOR_DIR"); d && *d) return d;
  const char* venv_env = std::getenv("GDR_MITSUBA_VENV");
  fs::path lib = fs::path(venv_env && *venv_env ? venv_env : GDR_SOURCE_DIR "/build/venv-mitsuba") / "lib";
  std::error_code ec;
  for (const fs::directory_entry& e : fs::directory_iterator(lib, ec)) {
    fs::path ior = e.path() / "site-packages" / "mitsuba" / "data" / "ior";
    if (fs::is_directory(ior, ec)) return ior.string();
  }
  return "";
}

TEST(NamedConductors, TableIsItsSourceConverted) {
  std::string dir = mitsuba_ior_dir();
  if (dir.empty()) GTEST_SKIP() << "no Mitsuba data/ior folder (set GDR_MITSUBA_IOR_DIR)";
  const std::string suffix = ".eta.spd";
  int names = 0;
  for (const fs::directory_entry& e : fs::directory_iterator(dir)) {
    std::string f = e.path().filename().string();
    if (f.size() <= suffix.size() || f.compare(f.size() - suffix.size(), suffix.size(), suffix) != 0) continue;
    std::string name = f.substr(0, f.size() - suffix.size());
    ++names;
    expect_same(lookup(name), conductor_from_spd_files(dir, name), name + " from " + dir);
  }
  EXPECT_GT(names, 0) << dir;
  // Nothing in the table that the data no longer has ("none" has no files).
  std::string list = named_conductor_list();
  EXPECT_EQ(std::count(list.begin(), list.end(), ',') + 1, names + 1) << list;
}

TEST(NamedConductors, SpdFilesAreReadLikeMitsuba) {
  test::TempFolder folder;
  std::string ok = folder.write("x.spd", "# comment\n400 1.5  # trailing\n\n  500\t2\r\n600 2.5\n");
  std::vector<std::pair<double, double>> s = read_spd_file(ok);
  ASSERT_EQ(s.size(), 3u);
  EXPECT_EQ(s[1].first, 500.0);
  EXPECT_EQ(s[1].second, 2.0);
  struct Bad {
    const char* text;
    const char* where;
  };
  for (const Bad& b : {Bad{"400 1\n500\n", ":2:"}, Bad{"400 1\n500 1 2\n", ":2:"}, Bad{"400 1\n400 2\n", ":2:"},
                       Bad{"400 x\n", ":1:"}, Bad{"400 nan\n500 1\n", ":1:"}, Bad{"400 1\n", "bad.spd:"}}) {
    std::string path = folder.write("bad.spd", b.text);
    try {
      read_spd_file(path);
      ADD_FAILURE() << "no error for " << b.text;
    } catch (const InputError& e) {
      EXPECT_NE(std::string(e.what()).find(path), std::string::npos) << e.what();
      EXPECT_NE(std::string(e.what()).find(b.where), std::string::npos) << e.what();
    }
  }
  EXPECT_THROW(read_spd_file(folder.path("missing.spd")), InputError);
}

}  // namespace
}  // namespace gdr
