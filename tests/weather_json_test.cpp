// Weather JSON files (weather/weather_json.h): round trip and one-line errors that name the
// file and the field.
#include <gtest/gtest.h>

#include <cmath>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "weather/weather_json.h"

namespace cloudsvc::weather {
namespace {

namespace fs = std::filesystem;

class WeatherJson : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::path(::testing::TempDir()) /
           ("cloudsvc_weather_json_" + std::to_string(::getpid()) + "_" +
            ::testing::UnitTest::GetInstance()->current_test_info()->name());
    fs::create_directories(dir_);
  }
  void TearDown() override {
    std::error_code ec;
    fs::remove_all(dir_, ec);
  }

  std::string write(const std::string& name, const std::string& text) {
    const fs::path p = dir_ / name;
    std::ofstream(p, std::ios::binary) << text;
    return p.string();
  }

  // Loads `text` from a file and returns the error message (fails if it loads).
  std::string error_of(const std::string& text) {
    const std::string path = write("w.json", text);
    try {
      load_weather_json(path);
    } catch (const WeatherFileError& e) {
      const std::string msg = e.what();
      EXPECT_EQ(msg.rfind(path + ": ", 0), 0u) << "message must start with the file: " << msg;
      EXPECT_EQ(msg.find('\n'), std::string::npos) << "message must be one line: " << msg;
      return msg.substr(path.size() + 2);  // without "<file>: "
    }
    ADD_FAILURE() << "loaded without error: " << text;
    return {};
  }

  fs::path dir_;
};

// A layer with all fields; `extra` is appended inside the layer object.
std::string layer(const std::string& fields) {
  return R"({"type": "cumulus", "base_m": 1000, "top_m": 2800, "coverage": 0.6)" +
         (fields.empty() ? std::string() : ", " + fields) + "}";
}
std::string doc(const std::string& layers) {
  return R"({"name": "t", "map_seed": 7, "layers": [)" + layers + "]}";
}

TEST_F(WeatherJson, LoadsTheDocumentedExample) {
  const std::string path = write(
      "example.json",
      R"({"name": "example", "map_seed": 7, "layers": [{"type": "cumulus", "base_m": 1000,
          "top_m": 2800, "coverage": 0.6, "density_scale": 1.0, "droplet_diameter_um": 20,
          "wind_mps": [5, -2.5]}]})");
  const Weather w = load_weather_json(path);
  EXPECT_EQ(w.name, "example");
  EXPECT_EQ(w.map_seed, 7u);
  ASSERT_EQ(w.layers.size(), 1u);
  const CloudLayer& l = w.layers[0];
  EXPECT_EQ(l.type, CloudType::Cumulus);
  EXPECT_EQ(l.base_m, 1000);
  EXPECT_EQ(l.top_m, 2800);
  EXPECT_EQ(l.coverage, 0.6);
  EXPECT_EQ(l.density_scale, 1.0);
  EXPECT_EQ(l.droplet_diameter_um, 20);
  EXPECT_EQ(l.wind.east_mps, 5);
  EXPECT_EQ(l.wind.north_mps, -2.5);
}

TEST_F(WeatherJson, OptionalFieldsDefaultFromTraits) {
  const Weather w = parse_weather_json(R"({"layers": [{"type": "st", "coverage": 1}]})", "s");
  EXPECT_EQ(w.name, "s");
  EXPECT_EQ(w.map_seed, Weather{}.map_seed);
  ASSERT_EQ(w.layers.size(), 1u);
  const CloudTypeTraits& st = cloud_type_traits(CloudType::Stratus);
  EXPECT_EQ(w.layers[0].type, CloudType::Stratus);
  EXPECT_EQ(w.layers[0].base_m, st.default_base_m);
  EXPECT_EQ(w.layers[0].top_m, st.default_top_m);
  EXPECT_EQ(w.layers[0].density_scale, st.default_density_scale);
  EXPECT_EQ(w.layers[0].droplet_diameter_um, st.default_droplet_diameter_um);
  EXPECT_EQ(w.layers[0].wind.east_mps, 0.0);

  // Only base given: the type's default thickness is kept above it.
  const Weather b = parse_weather_json(
      R"({"layers": [{"type": "cumulus", "coverage": 0.5, "base_m": 3000}]})", "b");
  const CloudTypeTraits& cu = cloud_type_traits(CloudType::Cumulus);
  EXPECT_EQ(b.layers[0].top_m, 3000 + cu.default_top_m - cu.default_base_m);
}

TEST_F(WeatherJson, LayersAreSortedByBase) {
  const Weather w = parse_weather_json(
      doc(R"({"type": "cirrus", "base_m": 9000, "top_m": 10000, "coverage": 0.2},)" +
          layer("")),
      "s");
  ASSERT_EQ(w.layers.size(), 2u);
  EXPECT_EQ(w.layers[0].type, CloudType::Cumulus);
  EXPECT_EQ(w.layers[1].type, CloudType::Cirrus);
}

TEST_F(WeatherJson, RoundTrip) {
  Weather w;
  w.name = "round \"trip\"";
  w.map_seed = 4294967295u;
  CloudLayer a = default_layer(CloudType::Stratocumulus);
  a.base_m = 1234.5678901234;
  a.top_m = 1834.1;
  a.coverage = 0.1 + 0.2;  // not exactly representable in decimal
  a.density_scale = 0.54;
  a.droplet_diameter_um = 16.25;
  a.wind = {-7.125, 1e-3};
  CloudLayer b = default_layer(CloudType::Cirrus);
  b.coverage = 1.0 / 3.0;
  w.layers = {a, b};
  w.ground_albedo = 0.1 + 0.7;
  w.visibility_m = 12345.678 + 0.1;  // m, not exactly representable in decimal
  ASSERT_EQ(validate(w), "");

  const std::string text = to_json(w);
  const Weather back = load_weather_json(write("rt.json", text));
  EXPECT_EQ(back.name, w.name);
  EXPECT_EQ(back.map_seed, w.map_seed);
  EXPECT_EQ(back.ground_albedo, w.ground_albedo);
  EXPECT_EQ(back.visibility_m, w.visibility_m);  // bit-exact
  ASSERT_EQ(back.layers.size(), w.layers.size());
  for (std::size_t i = 0; i < w.layers.size(); ++i) {
    const CloudLayer& x = w.layers[i];
    const CloudLayer& y = back.layers[i];
    EXPECT_EQ(x.type, y.type);
    EXPECT_EQ(x.base_m, y.base_m);  // bit-exact
    EXPECT_EQ(x.top_m, y.top_m);
    EXPECT_EQ(x.coverage, y.coverage);
    EXPECT_EQ(x.density_scale, y.density_scale);
    EXPECT_EQ(x.droplet_diameter_um, y.droplet_diameter_um);
    EXPECT_EQ(x.wind.east_mps, y.wind.east_mps);
    EXPECT_EQ(x.wind.north_mps, y.wind.north_mps);
  }
  EXPECT_EQ(to_json(back), text);
}

// "ground_albedo": the ground's grey albedo in [0, 1]; absent: unset (the renderer's default).
TEST_F(WeatherJson, GroundAlbedo) {
  EXPECT_FALSE(load_weather_json(write("a.json", doc(layer("")))).ground_albedo.has_value());
  const Weather snow = load_weather_json(write("b.json", R"({"ground_albedo": 0.8, "layers": []})"));
  ASSERT_TRUE(snow.ground_albedo.has_value());
  EXPECT_EQ(*snow.ground_albedo, 0.8);
  EXPECT_EQ(error_of(R"({"ground_albedo": 1.2, "layers": []})"), "ground_albedo: 1.2 out of range [0, 1]");
  EXPECT_EQ(error_of(R"({"ground_albedo": -0.1, "layers": []})"), "ground_albedo: -0.1 out of range [0, 1]");
  EXPECT_NE(error_of(R"({"ground_albedo": "snow", "layers": []})").find("ground_albedo"), std::string::npos);
  Weather w;
  w.ground_albedo = std::nan("");
  EXPECT_EQ(validate(w).rfind("ground_albedo", 0), 0u) << validate(w);
  w.ground_albedo = 1.0;
  EXPECT_EQ(validate(w), "");
}

// "visibility_m": the horizontal visibility at sea level, m, in [kMinVisibility_m,
// kMaxVisibility_m]; absent: unset (the renderer's own haze). Below the range is fog.
TEST_F(WeatherJson, Visibility) {
  EXPECT_FALSE(load_weather_json(write("a.json", doc(layer("")))).visibility_m.has_value());
  EXPECT_EQ(to_json(Weather{}).find("visibility_m"), std::string::npos) << "unset: not written";
  const Weather hazy = load_weather_json(write("b.json", R"({"visibility_m": 8000, "layers": []})"));
  ASSERT_TRUE(hazy.visibility_m.has_value());
  EXPECT_EQ(*hazy.visibility_m, 8000.0);
  for (const double edge : {kMinVisibility_m, kMaxVisibility_m}) {
    Weather w;
    w.visibility_m = edge;
    EXPECT_EQ(load_weather_json(write("edge.json", to_json(w))).visibility_m, edge);
  }
  EXPECT_EQ(error_of(R"({"visibility_m": 500, "layers": []})"),
            "visibility_m: 500 out of range [1000, 1000000] (below 1000 m is fog, not drawn)");
  EXPECT_EQ(error_of(R"({"visibility_m": 2e6, "layers": []})").rfind("visibility_m: 2000000 out of range [1000, 1000000]", 0),
            0u);
  EXPECT_EQ(error_of(R"({"visibility_m": -1, "layers": []})").rfind("visibility_m: -1 out of range", 0), 0u);
  EXPECT_NE(error_of(R"({"visibility_m": "10 km", "layers": []})").find("visibility_m"), std::string::npos);
  Weather w;
  w.visibility_m = std::nan("");
  EXPECT_EQ(validate(w).rfind("visibility_m", 0), 0u) << validate(w);
  w.visibility_m = 1.0e5;
  EXPECT_EQ(validate(w), "");
}

TEST_F(WeatherJson, CoverageOutOfRange) {
  EXPECT_EQ(error_of(doc(R"({"type": "cumulus", "base_m": 1000, "top_m": 2800, "coverage": 1.5})")),
            "layers[0].coverage: 1.5 out of range [0, 1]");
}

TEST_F(WeatherJson, TopBelowBase) {
  const std::string msg =
      error_of(doc(R"({"type": "cumulus", "base_m": 1000, "top_m": 900, "coverage": 0.5})"));
  EXPECT_EQ(msg.rfind("layers[0].top_m: must be greater than base_m (1000)", 0), 0u) << msg;
}

TEST_F(WeatherJson, OverlappingLayersNameThePairByFileIndex) {
  // File order: the upper layer first, so the indices differ from the sorted order.
  const std::string msg = error_of(doc(
      R"({"type": "altostratus", "base_m": 2500, "top_m": 4000, "coverage": 0.5},)" + layer("")));
  EXPECT_EQ(msg.rfind("layers[0]: ", 0), 0u) << msg;
  EXPECT_NE(msg.find("overlaps layers[1] (1000 to 2800 m)"), std::string::npos) << msg;
}

TEST_F(WeatherJson, TooManyLayers) {
  std::string layers;
  for (int i = 0; i < 5; ++i) {
    layers += (i ? "," : "") + std::string(R"({"type": "cumulus", "coverage": 0.5, "base_m": )") +
              std::to_string(1000 * (i + 1)) + R"(, "top_m": )" + std::to_string(1000 * (i + 1) + 500) +
              "}";
  }
  EXPECT_EQ(error_of(doc(layers)), "layers: 5 layers, at most 4 allowed");
}

TEST_F(WeatherJson, DropletTooLarge) {
  EXPECT_EQ(error_of(doc(layer(R"("droplet_diameter_um": 60)"))),
            "layers[0].droplet_diameter_um: 60 out of range [5, 50]");
}

TEST_F(WeatherJson, NonFiniteNumbersCannotBeWritten) {
  // JSON has no NaN or Infinity: the literals are syntax errors, with a position.
  const std::string nan_msg = error_of(doc(layer(R"("density_scale": NaN)")));
  EXPECT_NE(nan_msg.find("parse error at line 1, column"), std::string::npos) << nan_msg;
  EXPECT_NE(nan_msg.find("(byte "), std::string::npos) << nan_msg;
  const std::string inf_msg = error_of(doc(layer(R"("density_scale": Infinity)")));
  EXPECT_NE(inf_msg.find("parse error"), std::string::npos) << inf_msg;
  // A literal beyond double range would parse to Inf: rejected, with its line.
  const std::string big = error_of("{\"layers\": [\n" + layer(R"("density_scale": 1e999)") + "]}");
  EXPECT_EQ(big.rfind("line 2, column ", 0), 0u) << big;
  EXPECT_NE(big.find("1e999"), std::string::npos) << big;
}

TEST_F(WeatherJson, WrongTypes) {
  EXPECT_EQ(error_of(doc(R"({"type": "cumulus", "coverage": "lots"})")),
            R"(layers[0].coverage: expected a number, got string "lots")");
  EXPECT_EQ(error_of(doc(layer(R"("wind_mps": [1, true])"))),
            "layers[0].wind_mps[1]: expected a number, got boolean true");
  EXPECT_EQ(error_of(doc(layer(R"("wind_mps": 3)"))).rfind("layers[0].wind_mps: expected [east, north]", 0),
            0u);
  EXPECT_EQ(error_of(R"({"map_seed": -1})").rfind("map_seed: expected an integer", 0), 0u);
  EXPECT_EQ(error_of(R"({"map_seed": 7.5})").rfind("map_seed: expected an integer", 0), 0u);
  EXPECT_EQ(error_of(R"({"map_seed": 4294967296})").rfind("map_seed: expected an integer", 0), 0u);
  EXPECT_EQ(error_of(R"({"layers": {}})").rfind("layers: expected an array", 0), 0u);
  EXPECT_EQ(error_of(R"({"name": 3})").rfind("name: expected a string", 0), 0u);
  EXPECT_EQ(error_of("[1, 2]").rfind("(top level): expected an object", 0), 0u);
  EXPECT_EQ(error_of(doc(R"({"type": 7, "coverage": 0.5})")).rfind("layers[0].type: expected a string", 0),
            0u);
}

// Found while writing fuzz/weather_json_fuzz.cpp (with an input deeper than its 16 KiB
// inputs reach): the excerpt of a wrong value in a message was cut from the value's whole
// serialisation, which recurses once per nesting level, so a file of a few hundred KB of
// '[' overflowed the stack (SIGSEGV) instead of giving this error. The excerpt of an
// ordinary value is what it was (last case, and WrongTypes above).
TEST_F(WeatherJson, DeeplyNestedValuesGiveAnErrorNotACrash) {
  constexpr std::size_t kDepth = 300000;  // 100000 levels already overflowed 8 MiB of stack
  const std::string nested = std::string(kDepth, '[') + std::string(kDepth, ']');
  const std::string excerpt = std::string(37, '[') + "...";  // 40 characters at most
  EXPECT_EQ(error_of(doc(nested)), "layers[0]: expected an object, got array " + excerpt);
  EXPECT_EQ(error_of(doc(layer(R"("wind_mps": )" + nested))),
            "layers[0].wind_mps: expected [east, north] in m/s, got array " + excerpt);
  EXPECT_EQ(error_of(R"({"layers": [], "name": [1, {"a": [true, null, "x\"y"]}, 2.5]})"),
            R"(name: expected a string, got array [1,{"a":[true,null,"x\"y"]},2.5])");
}

TEST_F(WeatherJson, MissingAndUnknownValues) {
  EXPECT_EQ(error_of(doc(R"({"coverage": 0.5})")), "layers[0].type: missing (required)");
  EXPECT_EQ(error_of(doc(R"({"type": "cumulus"})")), "layers[0].coverage: missing (required)");
  EXPECT_EQ(error_of(doc(R"({"type": "cumulus-congestus", "coverage": 0.5})"))
                .rfind("layers[0].type: unknown cloud type \"cumulus-congestus\"", 0),
            0u);
  EXPECT_EQ(error_of(doc(R"({"type": "none", "coverage": 0.5})")).rfind("layers[0].type: unknown", 0),
            0u);
}

TEST_F(WeatherJson, UnknownKeysAreErrors) {
  EXPECT_EQ(error_of(doc(layer(R"("coverge": 0.5)"))).rfind("layers[0].coverge: unknown key", 0),
            0u);
  EXPECT_EQ(error_of(R"({"nmae": "x"})").rfind("nmae: unknown key", 0), 0u);
}

TEST_F(WeatherJson, DuplicateKeysAreErrors) {
  EXPECT_EQ(error_of(doc(R"({"type": "st", "coverage": 1}, )" + layer(R"("coverage": 0.9)")))
                .rfind("layers[1].coverage: duplicate key", 0),
            0u);
  EXPECT_EQ(error_of(R"({"map_seed": 1, "layers": [], "map_seed": 2})").rfind("map_seed: duplicate key", 0),
            0u);
  // The same key in different objects is fine.
  EXPECT_NO_THROW(parse_weather_json(doc(layer("") + ", " + R"({"type": "ci", "coverage": 0.1})"), "s"));
}

TEST_F(WeatherJson, SyntaxErrorGivesPosition) {
  const std::string msg = error_of("{\n  \"name\": \"x\",\n  \"layers\": [\n}\n");
  EXPECT_EQ(msg.rfind("parse error at line 4, column 1 (byte ", 0), 0u) << msg;
  EXPECT_NE(msg.find("syntax error"), std::string::npos) << msg;
  EXPECT_EQ(error_of("").rfind("parse error", 0), 0u);
}

TEST_F(WeatherJson, MissingFile) {
  const std::string path = (dir_ / "does-not-exist.json").string();
  try {
    load_weather_json(path);
    FAIL() << "loaded a missing file";
  } catch (const WeatherFileError& e) {
    EXPECT_EQ(std::string(e.what()), path + ": cannot open: No such file or directory");
  }
}

TEST_F(WeatherJson, DirectoryIsNotAFile) {
  try {
    load_weather_json(dir_.string());
    FAIL() << "loaded a directory";
  } catch (const WeatherFileError& e) {
    const std::string msg = e.what();
    EXPECT_EQ(msg.rfind(dir_.string() + ": cannot ", 0), 0u) << msg;
  }
}

}  // namespace
}  // namespace cloudsvc::weather
