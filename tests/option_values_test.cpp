// Flag values shared by the cloudsvc and sim_client command lines (common/option_values.h,
// option_paths.h, option_address.h, option_weather.h): each parser accepts its documented
// forms and refuses everything else with one line "<flag> <value>: <reason>" naming the
// flag. The programs' own tests (cli_options_test, cli_serve_options_test,
// simclient_cli_test, sim_client_integration_test) check the flags through the commands.
#include <gtest/gtest.h>
#include <unistd.h>

#include <CLI/CLI.hpp>
#include <filesystem>
#include <fstream>
#include <string>
#include <utility>

#include "common/option_address.h"
#include "common/option_paths.h"
#include "common/option_values.h"
#include "common/option_weather.h"

namespace cloudsvc::cli {
namespace {

namespace fs = std::filesystem;

// The FlagError message of f(), or "" when it does not throw one.
template <class F>
std::string flag_error(F&& f) {
  try {
    f();
  } catch (const FlagError& e) {
    return e.what();
  }
  return "";
}

// ---- errors -----------------------------------------------------------------------------

TEST(OptionErrors, OneLineNamingTheFlagAndTheValue) {
  EXPECT_EQ(flag_error([] { fail("--out", "", "expected a directory path"); }), "--out \"\": expected a directory path");
  EXPECT_EQ(flag_error([] { fail("--weather", "a\nb\r\tc", "bad"); }), "--weather a b  c: bad");
  EXPECT_EQ(range_text(Range{0.0, 1.0, false, ""}), "[0, 1]");
  EXPECT_EQ(range_text(Range{0.0, 170.0, true, "degrees"}), "(0, 170] (degrees)");
}

TEST(OptionErrors, AFlagGivenTwiceIsRefusedWithBothValues) {
  CLI::App app;
  app.option_defaults()->multi_option_policy(CLI::MultiOptionPolicy::TakeLast);
  std::string lat, lon;
  app.add_option("--lat", lat);
  app.add_option("--lon", lon);
  const char* argv[] = {"prog", "--lat", "1", "--lat", "2"};
  app.parse(5, argv);
  EXPECT_EQ(flag_error([&] { given(app, "--lat"); }), "--lat 1 2: given more than once (each flag at most once)");
  EXPECT_FALSE(given(app, "--lon"));
}

// ---- numbers ----------------------------------------------------------------------------

TEST(OptionNumbers, FiniteNumbersWithinTheRange) {
  const Range hz{0.0, 1000.0, true, "Hz"};
  EXPECT_EQ(parse_number("--fps", "2.5", hz), 2.5);
  EXPECT_EQ(parse_number("--fps", "+1e3", hz), 1000.0);
  EXPECT_EQ(flag_error([&] { parse_number("--fps", "nan", hz); }), "--fps nan: expected a finite number in (0, 1000] (Hz)");
  EXPECT_EQ(flag_error([&] { parse_number("--fps", "0", hz); }), "--fps 0: out of range (0, 1000] (Hz)");
  EXPECT_EQ(flag_error([] { parse_number("--lat", "95", Range{-90.0, 90.0, false, "degrees"}); }),
            "--lat 95: out of range [-90, 90] (degrees)");
  for (const char* bad : {"nan", "NaN", "inf", "-inf", "infinity", "abc", "", "1.5.2", "12abc", " 5", "5 ", "0x10",
                          "1e999", "++1", "+-1"}) {
    EXPECT_FALSE(parse_finite_number(bad).has_value()) << "'" << bad << "'";
    EXPECT_EQ(flag_error([&] { parse_number("--fps", bad, hz); }).rfind("--fps ", 0), 0u) << "'" << bad << "'";
  }
}

TEST(OptionNumbers, WholeNumbersAndFrameCounts) {
  EXPECT_EQ(parse_integer("--clients", "4", 1, 1024, "connections"), 4);
  EXPECT_EQ(parse_integer("--clients", "0007", 1, 1024, "connections"), 7);
  EXPECT_EQ(flag_error([] { parse_integer("--max-frames", "-3", 1, 10, "frames"); }),
            "--max-frames -3: expected a whole number in [1, 10] (frames)");
  EXPECT_EQ(flag_error([] { parse_integer("--max-clients", "0", 1, 1024, "clients"); }),
            "--max-clients 0: out of range [1, 1024] (clients)");
  for (const char* bad : {"", "1.5", "+1", "abc", "1e3", " 1"})
    EXPECT_NE(flag_error([&] { parse_integer("--n", bad, 0, 10, "x"); }).find("expected a whole number"),
              std::string::npos) << bad;
  EXPECT_NE(flag_error([] { parse_integer("--n", "99999999999", 0, 10, "x"); }).find("out of range"), std::string::npos);
  EXPECT_EQ(parse_frame_count("--window-frames", "0", "0 = until the window is closed"), 0);
  for (const char* bad : {"-1", "2.5", "", "2147483647", "99999999999"})
    EXPECT_NE(flag_error([&] { parse_frame_count("--window-frames", bad, "0 = forever"); }), "") << bad;
}

TEST(OptionNumbers, ImageSizes) {
  EXPECT_EQ(parse_image_size("--size", "64x36"), (std::pair<int, int>{64, 36}));
  EXPECT_EQ(parse_image_size("--size", "8192X1"), (std::pair<int, int>{8192, 1}));
  EXPECT_EQ(flag_error([] { parse_image_size("--size", "640"); }),
            "--size 640: expected WxH with W and H integers in [1, 8192] (pixels), e.g. 1280x720");
  EXPECT_EQ(flag_error([] { parse_image_size("--size", "8193x10"); }),
            "--size 8193x10: width 8193 out of range [1, 8192] (pixels)");
  EXPECT_EQ(flag_error([] { parse_image_size("--size", "10x0"); }), "--size 10x0: height 0 out of range [1, 8192] (pixels)");
  // A side too large for int is shown as typed.
  EXPECT_EQ(flag_error([] { parse_image_size("--size", "99999999999x5"); }),
            "--size 99999999999x5: width 99999999999 out of range [1, 8192] (pixels)");
  EXPECT_EQ(flag_error([] { parse_image_size("--max", "4096x10", 2048); }),
            "--max 4096x10: width 4096 out of range [1, 2048] (pixels)");
  for (const char* bad : {"0x0", "640x", "x360", "axb", "-5x5", "5x-5", "nanxnan", "640x360x2", "1.5x2", "+5x5", ""})
    EXPECT_EQ(flag_error([&] { parse_image_size("--size", bad); }).rfind("--size ", 0), 0u) << bad;
}

TEST(OptionNumbers, DurationsInSecondsMinutesOrHours) {
  EXPECT_DOUBLE_EQ(parse_duration("--duration", "90", 604800.0), 90.0);
  EXPECT_DOUBLE_EQ(parse_duration("--duration", "2.5s", 604800.0), 2.5);
  EXPECT_DOUBLE_EQ(parse_duration("--duration", "10m", 604800.0), 600.0);
  EXPECT_DOUBLE_EQ(parse_duration("--duration", "1.5h", 604800.0), 5400.0);
  for (const char* bad : {"", "0", "-1m", "10x", "m", "1e400", "nan", "169h", " 5"}) {
    const std::string e = flag_error([&] { parse_duration("--duration", bad, 604800.0); });
    EXPECT_EQ(e.rfind("--duration ", 0), 0u) << "'" << bad << "': " << e;
    EXPECT_NE(e.find("minutes (10m)"), std::string::npos) << e;
  }
}

TEST(OptionTimes, UtcIso8601WithZOrAnOffset) {
  EXPECT_EQ(parse_time("--valid-at", "2026-06-21T12:00Z"), 1782043200.0);
  EXPECT_EQ(parse_time("--time", "2026-06-21T13:30:00+01:00"), 1782043200.0 + 1800.0);
  for (const char* bad : {"2026-13-01T00:00Z", "yesterday", "2026-04-31T00:00:00Z", "2026-06-21", ""}) {
    const std::string e = flag_error([&] { parse_time("--time", bad); });
    EXPECT_EQ(e.rfind("--time ", 0), 0u) << e;
    EXPECT_NE(e.find("+hh:mm"), std::string::npos) << e;
  }
}

// ---- addresses --------------------------------------------------------------------------

TEST(OptionAddresses, TcpAndUnixForms) {
  Endpoint e = parse_endpoint("--connect", "tcp://127.0.0.1:7420", PortUse::Connect);
  EXPECT_EQ(e.kind, Endpoint::Kind::Tcp);
  EXPECT_EQ(e.host, "127.0.0.1");
  EXPECT_EQ(e.port, 7420);
  EXPECT_EQ(parse_endpoint("--connect", "tcp://[0::1]:7420", PortUse::Connect).host, "::1");
  EXPECT_EQ(parse_endpoint("--connect", "tcp://localhost:80", PortUse::Connect).host, "127.0.0.1");
  e = parse_endpoint("--connect", "unix:/tmp/x.sock", PortUse::Connect);
  EXPECT_EQ(e.kind, Endpoint::Kind::Unix);
  EXPECT_EQ(e.path, "/tmp/x.sock");
  // Port 0 (any free port) is for listening only.
  EXPECT_EQ(parse_endpoint("--listen", "tcp://127.0.0.1:0", PortUse::Listen).port, 0);
  EXPECT_EQ(flag_error([] { parse_endpoint("--connect", "tcp://127.0.0.1:0", PortUse::Connect); }),
            "--connect tcp://127.0.0.1:0: port 0 out of range [1, 65535]");
  EXPECT_EQ(flag_error([] { parse_endpoint("--listen", "tcp://127.0.0.1:65536", PortUse::Listen); }),
            "--listen tcp://127.0.0.1:65536: port 65536 out of range [0, 65535]");
  EXPECT_NE(flag_error([] { parse_endpoint("--listen", "unix:" + std::string(108, 'a'), PortUse::Listen); })
                .find("108 bytes, at most 107"),
            std::string::npos);
  EXPECT_NE(flag_error([] { parse_endpoint("--connect", "tcp://::1:7420", PortUse::Connect); }).find("in brackets"),
            std::string::npos);
  for (PortUse use : {PortUse::Listen, PortUse::Connect}) {
    for (const char* bad : {"127.0.0.1:7420", "tcp://example.com:7420", "tcp://[localhost]:7420", "tcp://[127.0.0.1]:7420",
                            "tcp://:7420", "tcp://[]:7420", "tcp://127.0.0.1", "tcp://127.0.0.1:", "tcp://127.0.0.1:+80",
                            "tcp://127.0.0.1:80.5", "tcp://[::1]", "tcp://[::1]80", "tcp://[::1:7420", "tcp://256.0.0.1:7420",
                            "tcp://127.0.0.1 :7420", "unix:", ""}) {
      EXPECT_EQ(flag_error([&] { parse_endpoint("--connect", bad, use); }).rfind("--connect ", 0), 0u) << bad;
    }
  }
}

TEST(OptionAddresses, UdpFormsForCigi) {
  UdpEndpoint u = parse_udp_endpoint("--cigi", "udp:8000", PortUse::Listen);
  EXPECT_EQ(u.host, "127.0.0.1");  // loopback unless an address is given
  EXPECT_EQ(u.port, 8000);
  EXPECT_EQ(u.text(), "udp:127.0.0.1:8000");
  u = parse_udp_endpoint("--cigi", "udp:0.0.0.0:0", PortUse::Listen);
  EXPECT_EQ(u.host, "0.0.0.0");
  EXPECT_EQ(u.port, 0);
  u = parse_udp_endpoint("--cigi-host", "udp:[0::1]:8001", PortUse::Connect);
  EXPECT_EQ(u.host, "::1");
  EXPECT_EQ(u.text(), "udp:[::1]:8001");
  EXPECT_EQ(parse_udp_endpoint("--cigi", "udp:localhost:9", PortUse::Listen).host, "127.0.0.1");
  EXPECT_NE(flag_error([] { parse_udp_endpoint("--cigi-host", "udp:0", PortUse::Connect); }).find("out of range [1, 65535]"),
            std::string::npos);
  for (const char* bad : {"8000", "udp:", "udp:x", "udp:127.0.0.1:", "udp:127.0.0.1:70000", "udp:example.com:8000",
                          "udp:::1:8000", "udp:[::1]", "tcp://127.0.0.1:8000", "udp://127.0.0.1:8000", ""}) {
    const std::string e = flag_error([&] { parse_udp_endpoint("--cigi", bad, PortUse::Listen); });
    EXPECT_EQ(e.rfind("--cigi ", 0), 0u) << bad;
    EXPECT_EQ(e.find('\n'), std::string::npos) << e;
  }
}

// ---- paths ------------------------------------------------------------------------------

class OptionPaths : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() / ("cloudsvc_option_paths_" + std::to_string(::getpid()));
    fs::remove_all(dir_);
    fs::create_directories(dir_);
    std::ofstream(dir_ / "file.txt") << "x";
  }
  void TearDown() override { fs::remove_all(dir_); }
  std::string path(const std::string& name) const { return (dir_ / name).string(); }
  fs::path dir_;
};

TEST_F(OptionPaths, OutputDirectoriesExistWritableOrCanBeCreated) {
  EXPECT_NO_THROW(check_output_directory("--out", dir_.string()));
  EXPECT_NO_THROW(check_output_directory("--out", path("a/b/c")));
  EXPECT_FALSE(fs::exists(path("a"))) << "the parser creates nothing";
  EXPECT_EQ(flag_error([&] { check_output_directory("--out", path("file.txt")); }),
            "--out " + path("file.txt") + ": exists and is not a directory");
  EXPECT_NE(flag_error([&] { check_output_directory("--out", path("file.txt/sub")); }), "");
  EXPECT_NE(flag_error([] { check_output_directory("--out", "/proc/cloudsvc-out"); }), "");
  EXPECT_EQ(flag_error([] { check_output_directory("--out", ""); }), "--out \"\": expected a directory path");
}

TEST_F(OptionPaths, OutputFilesInAWritableDirectory) {
  EXPECT_NO_THROW(check_writable_file("--json", path("report.json")));
  EXPECT_NO_THROW(check_writable_file("--json", path("file.txt")));  // replaced
  EXPECT_EQ(flag_error([&] { check_writable_file("--json", path("missing/r.json")); }),
            "--json " + path("missing/r.json") + ": directory " + path("missing") + " does not exist");
  EXPECT_EQ(flag_error([&] { check_writable_file("--json", dir_.string() + "/."); }),
            "--json " + dir_.string() + "/.: is a directory");
  EXPECT_NE(flag_error([] { check_writable_file("--json", "/proc/r.json"); }), "");
  EXPECT_NO_THROW(check_output_file("--out", path("view.PNG")));
  EXPECT_NO_THROW(check_output_file("--out", path("view.exr")));
  for (const char* bad : {"view.jpg", "view", ".png"})
    EXPECT_NE(flag_error([&] { check_output_file("--out", path(bad)); }).find("expected a file name ending in .png"),
              std::string::npos) << bad;
}

// ---- weather ----------------------------------------------------------------------------

TEST_F(OptionPaths, WeatherPresetsAndFiles) {
  EXPECT_NO_THROW(resolve_weather("--weather", "clear"));
  EXPECT_NO_THROW(weather_preset("--preset", "broken-cumulus"));
  const std::string unknown = flag_error([] { weather_preset("--preset", "no-such-preset"); });
  EXPECT_EQ(unknown.rfind("--preset no-such-preset: unknown weather preset (expected one of ", 0), 0u) << unknown;
  EXPECT_NE(unknown.find("broken-cumulus"), std::string::npos);
  std::ofstream(path("deck.json"))
      << R"({"name": "deck", "layers": [{"type": "stratocumulus", "base_m": 1200, "top_m": 1800, "coverage": 0.9}]})";
  EXPECT_EQ(resolve_weather("--weather", path("deck.json")).layers.size(), 1u);
  EXPECT_EQ(load_weather_file("--layers", path("deck.json")).layers.size(), 1u);
  EXPECT_EQ(flag_error([&] { load_weather_file("--layers", path("absent.json")); }),
            "--layers " + path("absent.json") + ": weather file not found");
  std::ofstream(path("broken.json")) << "{ \"layers\": [ {";
  EXPECT_EQ(flag_error([&] { resolve_weather("--weather", path("broken.json")); }).rfind("--weather " + path("broken.json") + ": ", 0),
            0u);
  EXPECT_EQ(flag_error([&] { load_weather_file("--layers", dir_.string()); }),
            "--layers " + dir_.string() + ": not a regular file");
}

}  // namespace
}  // namespace cloudsvc::cli
