// Command line of `cloudsvc serve`: defaults, every flag's valid values, help, and the
// error contract (one line on stderr starting "cloudsvc serve: " and naming the flag and
// the given value, exit code 2) for each kind of bad input.
#include <gtest/gtest.h>
#include <sys/socket.h>
#include <sys/un.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "service/render_options.h"
#include "weather/presets.h"
#include "weather/weather_json.h"
#include "cli_test_support.h"
#include "grib_test_support.h"

namespace cloudsvc {
namespace {

namespace fs = std::filesystem;

using test::Outcome;
using test::run;

std::string joined(const std::vector<std::string>& args) {
  std::string text = "cloudsvc";
  for (const std::string& a : args) text += " " + a;
  return text;
}

// `cloudsvc serve <flags>` is rejected: exit 2, only the error line on stderr, and the
// line starts with the command and names `flag` and, if not empty, `value`.
void expect_serve_rejected(const std::vector<std::string>& flags, const std::string& flag,
                           const std::string& value = "") {
  std::vector<std::string> args{"serve"};
  args.insert(args.end(), flags.begin(), flags.end());
  SCOPED_TRACE(joined(args));
  const Outcome r = run(args);
  EXPECT_EQ(r.cmd.exit_code, 2);
  EXPECT_EQ(r.err, r.cmd.error + "\n");
  EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1);
  EXPECT_TRUE(r.out.empty()) << r.out;
  EXPECT_EQ(r.cmd.error.rfind("cloudsvc serve: ", 0), 0u) << r.cmd.error;
  EXPECT_NE(r.cmd.error.find(flag), std::string::npos) << r.cmd.error;
  EXPECT_NE(r.cmd.error.find(value), std::string::npos) << r.cmd.error;
}

void expect_listen_rejected(const std::string& address) {
  expect_serve_rejected({"--listen", address}, "--listen", address);
}

// `cloudsvc serve <flags>` is accepted silently; its options.
ServeOptions serve_with(const std::vector<std::string>& flags) {
  std::vector<std::string> args{"serve"};
  args.insert(args.end(), flags.begin(), flags.end());
  SCOPED_TRACE(joined(args));
  const Outcome r = run(args);
  EXPECT_EQ(r.cmd.exit_code, -1) << r.cmd.error;
  EXPECT_EQ(r.cmd.kind, ParsedCommand::Kind::Serve);
  EXPECT_TRUE(r.err.empty()) << r.err;
  EXPECT_TRUE(r.out.empty()) << r.out;
  return r.cmd.serve;
}

ListenAddress single_listen(const std::string& address) {
  const ServeOptions o = serve_with({"--listen", address});
  EXPECT_EQ(o.listen.size(), 1u);
  return o.listen.empty() ? ListenAddress{} : o.listen.front();
}

double now_unix_s() {
  return std::chrono::duration<double>(std::chrono::system_clock::now().time_since_epoch())
      .count();
}

// A fresh directory under the system temp directory, removed afterwards.
class CliServeOptionsTest : public testing::Test {
 protected:
  void SetUp() override {
    const auto* info = testing::UnitTest::GetInstance()->current_test_info();
    dir_ = fs::temp_directory_path() /
           ("cloudsvc_serve_" + std::to_string(getpid()) + "_" + info->name());
    fs::remove_all(dir_);
    fs::create_directories(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }

  std::string path(const std::string& name) const { return (dir_ / name).string(); }
  std::string write_file(const std::string& name, const std::string& text) const {
    std::ofstream(path(name)) << text;
    return path(name);
  }
  // A path in dir_ of exactly `bytes` bytes.
  std::string path_of_length(std::size_t bytes) const {
    const std::string prefix = path("s");
    return prefix + std::string(bytes - prefix.size(), 'k');
  }
  // Binds (and closes) a Unix socket at `file`, leaving the socket file behind.
  static void make_socket_file(const std::string& file) {
    const int fd = ::socket(AF_UNIX, SOCK_STREAM, 0);
    ASSERT_GE(fd, 0);
    sockaddr_un addr{};
    addr.sun_family = AF_UNIX;
    std::strncpy(addr.sun_path, file.c_str(), sizeof addr.sun_path - 1);
    const int rc = ::bind(fd, reinterpret_cast<const sockaddr*>(&addr), sizeof addr);
    ::close(fd);
    ASSERT_EQ(rc, 0) << std::strerror(errno);
    ASSERT_TRUE(fs::is_socket(file));
  }

  fs::path dir_;
};

// ---- defaults and help ---------------------------------------------------------------

TEST_F(CliServeOptionsTest, Defaults) {
  const double before = now_unix_s();
  const ServeOptions o = serve_with({});
  const double after = now_unix_s();
  ASSERT_EQ(o.listen.size(), 1u);
  EXPECT_EQ(o.listen[0].kind, ListenAddress::Kind::Tcp);
  EXPECT_EQ(o.listen[0].host, "127.0.0.1");
  EXPECT_EQ(o.listen[0].port, 7420);
  EXPECT_EQ(o.listen[0].text, "tcp://127.0.0.1:7420");
  EXPECT_TRUE(o.shm_name.empty());
  EXPECT_EQ(o.shm_max_width, 1920);
  EXPECT_EQ(o.shm_max_height, 1080);
  EXPECT_FALSE(o.window);
  EXPECT_FALSE(o.cumulus_domes);
  EXPECT_TRUE(serve_with({"--cumulus-domes"}).cumulus_domes);
  EXPECT_FALSE(o.noise_tiling);
  EXPECT_TRUE(serve_with({"--noise-tiling"}).noise_tiling);
  EXPECT_EQ(o.cloud_phase, model::CloudPhaseModel::kFit);
  EXPECT_EQ(serve_with({"--cloud-phase", "mie"}).cloud_phase, model::CloudPhaseModel::kMie);
  expect_serve_rejected({"--cloud-phase", "rayleigh"}, "--cloud-phase", "rayleigh");
  EXPECT_TRUE(o.out_dir.empty());
  EXPECT_EQ(o.weather_arg, "broken-cumulus");
  const auto preset = weather::preset("broken-cumulus");
  ASSERT_TRUE(preset.has_value());
  EXPECT_FALSE(o.weather.layers.empty());
  EXPECT_EQ(o.weather.layers.size(), preset->layers.size());
  EXPECT_TRUE(o.time_text.empty()) << "no --time: the current time, no text";
  EXPECT_GE(o.unix_time_s, before);
  EXPECT_LE(o.unix_time_s, after);
  EXPECT_EQ(o.width, 640);
  EXPECT_EQ(o.height, 360);
  EXPECT_DOUBLE_EQ(o.fov_deg, 60.0);
  EXPECT_EQ(o.max_clients, 16);
  EXPECT_EQ(o.exit_after_frames, 0);
  EXPECT_EQ(o.socket_mode, 0600u) << "only the service's user may connect";
  EXPECT_EQ(o.shm_mode, 0600u) << "only the service's user may read the frames";
  EXPECT_EQ(o.idle_timeout_s, 60);
  EXPECT_EQ(o.max_view_width, 3840);
  EXPECT_EQ(o.max_view_height, 2160);
  EXPECT_EQ(o.tile_budget_mib, 256);
  EXPECT_TRUE(o.ready_file.empty());
}

TEST_F(CliServeOptionsTest, HelpDocumentsEveryFlagWithUnitsRangesDefaultsAndExample) {
  const Outcome r = run({"serve", "--help"});
  EXPECT_EQ(r.cmd.exit_code, 0);
  EXPECT_TRUE(r.err.empty()) << r.err;
  for (const char* text :
       {"--listen", "--shm", "--shm-max-size", "--window", "--out-dir", "--weather", "--cumulus-domes", "--noise-tiling", "--cloud-phase", "--time",
        "--size", "--fov", "--max-clients", "--exit-after-frames", "tcp://HOST:PORT", "--cigi", "--cigi-host",
        "--cigi-mode", "--cigi-rate", "udp:HOST:PORT", "NAME-view<ID>",
        "unix:PATH", "[0, 65535]", "107 bytes", "--socket-mode", "--shm-mode", "0600", "--idle-timeout",
        "--max-view-size", "default 3840x2160", "--tile-budget", "Overloaded", "--ready-file", "localhost", "[::1]", "not resolved",
        "exposes the service", "default tcp://127.0.0.1:7420", "1..200", "default 1920x1080",
        "[1, 8192]", "pixels", "(0, 170] (degrees)", "default 60", "[1, 1024] (clients)",
        "default 16", "ISO 8601", "UTC", "current time", "broken-cumulus", ".json",
        "PNG", "SIGINT", "SIGTERM", "Exit codes", "2 bad input",
        "cloudsvc serve --listen tcp://127.0.0.1:7420 --listen unix:/tmp/cloudsvc.sock --shm "
        "cloudsvc-frames --out-dir frames/"}) {
    EXPECT_NE(r.out.find(text), std::string::npos) << "missing: " << text << "\n" << r.out;
  }
  EXPECT_EQ(r.out.find("--lat"), std::string::npos);
}

TEST_F(CliServeOptionsTest, TopLevelHelpAndMessagesListServe) {
  const Outcome help = run({"--help"});
  EXPECT_EQ(help.cmd.exit_code, 0);
  EXPECT_NE(help.out.find("serve"), std::string::npos) << help.out;
  EXPECT_NE(help.out.find("cloudsvc serve --help"), std::string::npos) << help.out;

  EXPECT_EQ(run({"bogus"}).cmd.error,
            "cloudsvc: bogus: unknown sub-command (expected render, demo, serve or weather-info)");
  const Outcome none = run({});
  EXPECT_EQ(none.cmd.exit_code, 2);
  EXPECT_EQ(none.cmd.error, "cloudsvc: missing sub-command (expected render, demo, serve or weather-info)");
  EXPECT_NE(none.err.find("serve"), std::string::npos);
}

TEST_F(CliServeOptionsTest, HelpWinsOverBadValues) {
  EXPECT_EQ(run({"serve", "--listen", "bogus", "--help"}).cmd.exit_code, 0);
}

// ---- --listen ----------------------------------------------------------------------------

TEST_F(CliServeOptionsTest, TcpAddresses) {
  const ListenAddress v4 = single_listen("tcp://192.168.1.20:8000");
  EXPECT_EQ(v4.kind, ListenAddress::Kind::Tcp);
  EXPECT_EQ(v4.host, "192.168.1.20");
  EXPECT_EQ(v4.port, 8000);
  EXPECT_EQ(v4.text, "tcp://192.168.1.20:8000");

  const ListenAddress v6 = single_listen("tcp://[::1]:1");
  EXPECT_EQ(v6.host, "::1");
  EXPECT_EQ(v6.port, 1);
  EXPECT_EQ(single_listen("tcp://[0:0:0:0:0:0:0:1]:65535").host, "::1") << "canonical form";
  EXPECT_EQ(single_listen("tcp://[0:0:0:0:0:0:0:1]:65535").port, 65535);

  const ListenAddress local = single_listen("tcp://localhost:7421");
  EXPECT_EQ(local.host, "127.0.0.1");
  EXPECT_EQ(local.port, 7421);
  EXPECT_EQ(local.text, "tcp://localhost:7421");

  // Not loopback: allowed (documented as exposing the service), nothing printed.
  EXPECT_EQ(single_listen("tcp://0.0.0.0:7420").host, "0.0.0.0");
  EXPECT_EQ(single_listen("tcp://[::]:7420").host, "::");
}

TEST_F(CliServeOptionsTest, UnixAddresses) {
  const std::string sock = path("svc.sock");
  const ListenAddress a = single_listen("unix:" + sock);
  EXPECT_EQ(a.kind, ListenAddress::Kind::Unix);
  EXPECT_EQ(a.path, sock);
  EXPECT_EQ(a.text, "unix:" + sock);
  EXPECT_FALSE(fs::exists(sock)) << "validation must not create the socket";

  const std::string longest = path_of_length(107);
  EXPECT_EQ(single_listen("unix:" + longest).path, longest);

  const std::string stale = path("stale.sock");
  make_socket_file(stale);
  EXPECT_EQ(single_listen("unix:" + stale).path, stale) << "an existing socket may be replaced";
}

TEST_F(CliServeOptionsTest, SeveralAddressesKeepTheirOrder) {
  const std::string sock = path("a.sock");
  const ServeOptions o = serve_with({"--listen", "tcp://127.0.0.1:7420", "--listen",
                                     "unix:" + sock, "--listen=tcp://[::1]:7420", "--listen",
                                     "tcp://0.0.0.0:7421"});
  ASSERT_EQ(o.listen.size(), 4u);
  EXPECT_EQ(o.listen[0].host, "127.0.0.1");
  EXPECT_EQ(o.listen[1].kind, ListenAddress::Kind::Unix);
  EXPECT_EQ(o.listen[1].path, sock);
  EXPECT_EQ(o.listen[2].host, "::1");
  EXPECT_EQ(o.listen[2].port, 7420);
  EXPECT_EQ(o.listen[3].port, 7421);
  // Different families on the same port do not overlap.
  EXPECT_EQ(serve_with({"--listen", "tcp://0.0.0.0:7420", "--listen", "tcp://[::]:7420"})
                .listen.size(),
            2u);
}

TEST_F(CliServeOptionsTest, BadSchemes) {
  for (const char* address : {"http://127.0.0.1:7420", "TCP://127.0.0.1:7420", "127.0.0.1:7420",
                              "tcp:/127.0.0.1:7420", "udp://127.0.0.1:7420", "/tmp/x.sock",
                              "unix/tmp/x.sock"}) {
    expect_listen_rejected(address);
  }
  expect_serve_rejected({"--listen", ""}, "--listen", "\"\"");
  expect_serve_rejected({"--listen"}, "--listen");
  expect_serve_rejected({"--listen="}, "--listen");
}

TEST_F(CliServeOptionsTest, BadPorts) {
  for (const char* address :
       {"tcp://127.0.0.1:65536", "tcp://127.0.0.1:abc", "tcp://127.0.0.1",
        "tcp://127.0.0.1:", "tcp://127.0.0.1:-1", "tcp://127.0.0.1:+80", "tcp://127.0.0.1:80.5",
        "tcp://127.0.0.1:99999999999", "tcp://[::1]", "tcp://[::1]:", "tcp://[::1]80"}) {
    expect_listen_rejected(address);
  }
  const Outcome r = run({"serve", "--listen", "tcp://127.0.0.1:65536"});
  EXPECT_EQ(r.cmd.error,
            "cloudsvc serve: --listen tcp://127.0.0.1:65536: port 65536 out of range [0, 65535]");
  // Port 0: the kernel picks (reported in --ready-file); two such addresses do not clash.
  const ServeOptions any = serve_with({"--listen", "tcp://127.0.0.1:0", "--listen", "tcp://127.0.0.1:0"});
  ASSERT_EQ(any.listen.size(), 2u);
  EXPECT_EQ(any.listen[0].port, 0);
}

TEST_F(CliServeOptionsTest, HostsMustBeNumericOrLocalhost) {
  for (const char* address :
       {"tcp://example.com:7420", "tcp://my-host:7420", "tcp://LOCALHOST.:7420",
        "tcp://localhost.localdomain:7420", "tcp://:7420", "tcp://[]:7420", "tcp://::1:7420",
        "tcp://[127.0.0.1]:7420", "tcp://[localhost]:7420", "tcp://1.2.3:7420",
        "tcp://256.0.0.1:7420", "tcp://01.2.3.4:7420", "tcp://[::1:7420", "tcp://[fe80::1%lo]:7420",
        "tcp://127.0.0.1 :7420"}) {
    expect_listen_rejected(address);
  }
}

TEST_F(CliServeOptionsTest, BadUnixPaths) {
  expect_listen_rejected("unix:");
  expect_listen_rejected("unix:" + path_of_length(108));
  expect_listen_rejected("unix:" + path("missing/dir/x.sock"));
  const std::string file = write_file("plain.txt", "x");
  expect_listen_rejected("unix:" + file);           // exists, not a socket
  expect_listen_rejected("unix:" + file + "/x.sock");  // parent is a file
  expect_listen_rejected("unix:" + dir_.string());  // a directory
  expect_listen_rejected("unix:" + dir_.string() + "/");
  expect_listen_rejected("unix:/proc/cloudsvc.sock");  // not writable
  const Outcome r = run({"serve", "--listen", "unix:" + path_of_length(108)});
  EXPECT_NE(r.cmd.error.find("108 bytes, at most 107"), std::string::npos) << r.cmd.error;
}

TEST_F(CliServeOptionsTest, DuplicateAddresses) {
  const auto expect_pair_rejected = [](const std::string& first, const std::string& second) {
    expect_serve_rejected({"--listen", first, "--listen", second}, "--listen", second);
  };
  expect_pair_rejected("tcp://127.0.0.1:7420", "tcp://127.0.0.1:7420");
  expect_pair_rejected("tcp://localhost:7420", "tcp://127.0.0.1:7420");
  expect_pair_rejected("tcp://[::1]:7420", "tcp://[0::1]:7420");
  expect_pair_rejected("tcp://0.0.0.0:7420", "tcp://127.0.0.1:7420");  // wildcard covers it
  expect_pair_rejected("tcp://[::1]:9000", "tcp://[::]:9000");
  expect_pair_rejected("unix:" + path("a.sock"), "unix:" + path("a.sock"));
  expect_pair_rejected("unix:" + path("a.sock"), "unix:" + path("sub/../a.sock"));
  const Outcome r = run({"serve", "--listen", "tcp://localhost:7420", "--listen",
                         "tcp://127.0.0.1:7420"});
  EXPECT_EQ(r.cmd.error,
            "cloudsvc serve: --listen tcp://127.0.0.1:7420: same address as --listen "
            "tcp://localhost:7420 (each address at most once)");
}

// ---- shared memory, window, files --------------------------------------------------------

TEST_F(CliServeOptionsTest, SinkFlags) {
  const std::string nested = path("frames/a/b");
  const ServeOptions o = serve_with({"--shm", "Cloud_svc-1.frames", "--shm-max-size", "8192x1",
                                     "--size", "640x1", "--window", "--out-dir", nested});
  EXPECT_EQ(o.shm_name, "Cloud_svc-1.frames");
  EXPECT_EQ(o.shm_max_width, 8192);
  EXPECT_EQ(o.shm_max_height, 1);
  EXPECT_TRUE(o.window);
  EXPECT_EQ(o.out_dir, nested);
  EXPECT_FALSE(fs::exists(nested)) << "the service, not the parser, creates the directory";

  EXPECT_EQ(serve_with({"--shm", std::string(200, 'n')}).shm_name, std::string(200, 'n'));
  EXPECT_EQ(serve_with({"--shm", "x"}).shm_max_width, 1920);
  EXPECT_EQ(serve_with({"--out-dir", dir_.string()}).out_dir, dir_.string());
  EXPECT_EQ(serve_with({"--shm", "ring", "--shm-max-size", "640x360"}).shm_max_height, 360);
}

TEST_F(CliServeOptionsTest, BadShmNames) {
  for (const std::string& name : {std::string(""), std::string("."), std::string(".."),
                                 std::string("a/b"), std::string("/frames"),
                                 std::string("a b"), std::string("caf\xc3\xa9"),
                                 std::string("x*"), std::string(201, 'n')}) {
    expect_serve_rejected({"--shm", name}, "--shm", name.empty() ? "\"\"" : name);
  }
}

// --cigi and its companions (docs/CIGI.md): a UDP address (loopback when only a port is
// given), where answers go, the pacing; the companions only with --cigi.
TEST_F(CliServeOptionsTest, CigiFlags) {
  EXPECT_FALSE(serve_with({}).cigi);
  const ServeOptions o = serve_with({"--cigi", "udp:8000"});
  ASSERT_TRUE(o.cigi);
  EXPECT_EQ(o.cigi->listen.host, "127.0.0.1");
  EXPECT_EQ(o.cigi->listen.port, 8000);
  EXPECT_FALSE(o.cigi->host);
  EXPECT_EQ(o.cigi->pacing, CigiPacing::Synchronous);
  const ServeOptions a = serve_with({"--cigi", "udp:0.0.0.0:0", "--cigi-host", "udp:[::1]:8001", "--cigi-mode", "async",
                                     "--cigi-rate", "30", "--listen", "tcp://127.0.0.1:0"});
  ASSERT_TRUE(a.cigi);
  EXPECT_EQ(a.cigi->listen.host, "0.0.0.0");
  ASSERT_TRUE(a.cigi->host);
  EXPECT_EQ(a.cigi->host->text(), "udp:[::1]:8001");
  EXPECT_EQ(a.cigi->pacing, CigiPacing::Asynchronous);
  EXPECT_DOUBLE_EQ(a.cigi->rate_hz, 30.0);
  EXPECT_EQ(a.listen.size(), 1u) << "--cigi goes with --listen";

  expect_serve_rejected({"--cigi", "tcp://127.0.0.1:8000"}, "--cigi", "tcp://127.0.0.1:8000");
  expect_serve_rejected({"--cigi", "udp:70000"}, "--cigi", "udp:70000");
  expect_serve_rejected({"--cigi", "udp:8000", "--cigi-host", "udp:0"}, "--cigi-host", "udp:0");
  expect_serve_rejected({"--cigi", "udp:8000", "--cigi-mode", "lockstep"}, "--cigi-mode", "lockstep");
  expect_serve_rejected({"--cigi", "udp:8000", "--cigi-rate", "30"}, "--cigi-rate", "only valid with --cigi-mode async");
  expect_serve_rejected({"--cigi", "udp:8000", "--cigi-mode", "async", "--cigi-rate", "0"}, "--cigi-rate", "0");
  expect_serve_rejected({"--cigi-mode", "async"}, "--cigi-mode", "only valid together with --cigi");
  expect_serve_rejected({"--cigi-host", "udp:1.2.3.4:5"}, "--cigi-host", "only valid together with --cigi");
  expect_serve_rejected({"--cigi", "udp:8000", "--shm", std::string(195, 'n')}, "--shm", "-view<ID>");
}

// Quality per CIGI view: one preset for every view, overridden per view ID.
TEST_F(CliServeOptionsTest, CigiQualityFlags) {
  const ServeOptions d = serve_with({"--cigi", "udp:8000"});
  ASSERT_TRUE(d.cigi);
  EXPECT_EQ(d.cigi->quality_of(0), "default");
  EXPECT_EQ(d.cigi->quality_of(7), "default");
  const ServeOptions o = serve_with({"--cigi", "udp:8000", "--cigi-quality", "high", "--cigi-view-quality", "1=low",
                                     "--cigi-view-quality", "65535=naive"});
  ASSERT_TRUE(o.cigi);
  EXPECT_EQ(o.cigi->quality_of(0), "high");
  EXPECT_EQ(o.cigi->quality_of(1), "low");
  EXPECT_EQ(o.cigi->quality_of(2), "high");
  EXPECT_EQ(o.cigi->quality_of(65535), "naive");

  expect_serve_rejected({"--cigi", "udp:8000", "--cigi-quality", "best"}, "--cigi-quality", "expected one of");
  expect_serve_rejected({"--cigi", "udp:8000", "--cigi-quality", "truth"}, "--cigi-quality", "truth");
  expect_serve_rejected({"--cigi", "udp:8000", "--cigi-view-quality", "1"}, "--cigi-view-quality", "ID=PRESET");
  expect_serve_rejected({"--cigi", "udp:8000", "--cigi-view-quality", "1=fast"}, "--cigi-view-quality", "1=fast");
  expect_serve_rejected({"--cigi", "udp:8000", "--cigi-view-quality", "65536=low"}, "--cigi-view-quality", "65536");
  expect_serve_rejected({"--cigi", "udp:8000", "--cigi-view-quality", "1.5=low"}, "--cigi-view-quality", "integer");
  expect_serve_rejected({"--cigi", "udp:8000", "--cigi-view-quality", "-1=low"}, "--cigi-view-quality", "-1");
  expect_serve_rejected({"--cigi", "udp:8000", "--cigi-view-quality", "1=low", "--cigi-view-quality", "1=high"},
                        "--cigi-view-quality", "given twice");
  expect_serve_rejected({"--cigi-quality", "low"}, "--cigi-quality", "only valid together with --cigi");
  expect_serve_rejected({"--cigi-view-quality", "1=low"}, "--cigi-view-quality", "only valid together with --cigi");
}

TEST_F(CliServeOptionsTest, BadShmSizes) {
  for (const char* value : {"0x0", "8193x100", "100x8193", "640", "axb", "-5x5", "1.5x2"}) {
    expect_serve_rejected({"--shm", "ring", "--shm-max-size", value}, "--shm-max-size", value);
  }
  expect_serve_rejected({"--shm-max-size", "640x360"}, "--shm-max-size", "640x360");  // no --shm
  // The initial view must fit the ring.
  expect_serve_rejected({"--shm", "ring", "--size", "1921x100"}, "--size", "1921x100");
  expect_serve_rejected({"--shm", "ring", "--shm-max-size", "320x200"}, "--shm-max-size",
                        "320x200");
}

TEST_F(CliServeOptionsTest, BadOutputDirectories) {
  const std::string file = write_file("file.txt", "x");
  expect_serve_rejected({"--out-dir", file}, "--out-dir", file);
  expect_serve_rejected({"--out-dir", file + "/sub"}, "--out-dir", file + "/sub");
  expect_serve_rejected({"--out-dir", "/proc/cloudsvc-frames"}, "--out-dir");
  expect_serve_rejected({"--out-dir", ""}, "--out-dir");
}

// ---- scene and limits ------------------------------------------------------------------

TEST_F(CliServeOptionsTest, SceneFlags) {
  const ServeOptions o = serve_with({"--time", "2026-03-01T12:30:00+02:00", "--size", "1280x720",
                                     "--fov", "170", "--weather", "overcast-stratus"});
  EXPECT_EQ(o.time_text, "2026-03-01T12:30:00+02:00");
  EXPECT_DOUBLE_EQ(o.unix_time_s, 1772361000.0);
  EXPECT_EQ(o.width, 1280);
  EXPECT_EQ(o.height, 720);
  EXPECT_DOUBLE_EQ(o.fov_deg, 170.0);
  EXPECT_EQ(o.weather_arg, "overcast-stratus");
  EXPECT_EQ(o.weather.layers.size(), weather::preset("overcast-stratus")->layers.size());

  const auto cb = weather::preset("cumulonimbus");
  ASSERT_TRUE(cb.has_value());
  const std::string file = write_file("sky.json", weather::to_json(*cb));
  const ServeOptions f = serve_with({"--weather", file});
  ASSERT_EQ(f.weather.layers.size(), cb->layers.size());
  ASSERT_FALSE(f.weather.layers.empty());
  EXPECT_DOUBLE_EQ(f.weather.layers[0].base_m, cb->layers[0].base_m);
  // A forecast file is read, not taken for an unknown preset.
  EXPECT_EQ(run({"serve", "--weather", "/no/such/gfs.grib2"}).cmd.error,
            "cloudsvc serve: --weather /no/such/gfs.grib2: cannot open: No such file or directory");
  // Several GRIB2 files make one forecast (one step each here), given after one --weather
  // or with the flag repeated; a preset or weather file comes alone.
  test::GribTempDir dir;
  std::vector<std::string> steps;
  for (long hour : {0L, 6L}) {
    steps.push_back(dir.file("step" + std::to_string(hour) + ".grib2").string());
    test::append_cloud_field(steps.back(), 6, 1, 214, 80.0, hour);
  }
  for (const auto& args : {std::vector<std::string>{"--weather", steps[0], steps[1]},
                           std::vector<std::string>{"--weather", steps[0], "--weather", steps[1]}}) {
    const ServeOptions two = serve_with(args);
    ASSERT_TRUE(two.forecast);
    EXPECT_EQ(two.forecast->valid_times().size(), 2u);
    EXPECT_EQ(two.weather_arg, steps[0] + " " + steps[1]);
  }
  EXPECT_EQ(run({"serve", "--weather", "clear", steps[0]}).cmd.error,
            "cloudsvc serve: --weather clear " + steps[0] +
                ": 'clear' among several values: several are only GRIB2 or METAR files; a preset or a .json "
                "weather file comes alone");
}

TEST_F(CliServeOptionsTest, LimitFlags) {
  EXPECT_EQ(serve_with({"--max-clients", "1"}).max_clients, 1);
  EXPECT_EQ(serve_with({"--max-clients", "1024"}).max_clients, 1024);
  EXPECT_EQ(serve_with({"--exit-after-frames", "0"}).exit_after_frames, 0);
  EXPECT_EQ(serve_with({"--exit-after-frames", "300"}).exit_after_frames, 300);
  EXPECT_EQ(serve_with({"--socket-mode", "0660"}).socket_mode, 0660u);
  EXPECT_EQ(serve_with({"--socket-mode", "777"}).socket_mode, 0777u);
  EXPECT_EQ(serve_with({"--shm", "x", "--shm-mode", "0640"}).shm_mode, 0640u);
  EXPECT_EQ(serve_with({"--idle-timeout", "0"}).idle_timeout_s, 0);
  EXPECT_EQ(serve_with({"--idle-timeout", "5"}).idle_timeout_s, 5);
  const ServeOptions v = serve_with({"--max-view-size", "1920x1080", "--size", "320x180"});
  EXPECT_EQ(v.max_view_width, 1920);
  EXPECT_EQ(v.max_view_height, 1080);
  EXPECT_EQ(serve_with({"--tile-budget", "16"}).tile_budget_mib, 16);
  EXPECT_EQ(serve_with({"--ready-file", path("ready")}).ready_file, path("ready"));
}

TEST_F(CliServeOptionsTest, BadSceneValues) {
  for (const char* value : {"2026-13-01T00:00Z", "yesterday", "2026-06-21", ""}) {
    expect_serve_rejected({"--time", value}, "--time");
  }
  expect_serve_rejected({"--weather", "no-such-preset"}, "--weather", "no-such-preset");
  expect_serve_rejected({"--weather", path("missing.json")}, "--weather", path("missing.json"));
  const std::string broken = write_file("broken.json", "{ \"layers\": [ {");
  expect_serve_rejected({"--weather", broken}, "--weather", broken);
  for (const char* value : {"0x0", "8193x100", "640", "axb"}) {
    expect_serve_rejected({"--size", value}, "--size", value);
  }
  for (const char* value : {"0", "170.01", "nan", "abc", ""}) {
    expect_serve_rejected({"--fov", value}, "--fov");
  }
}

TEST_F(CliServeOptionsTest, BadLimits) {
  for (const char* value : {"0", "1025", "-1", "abc", "1.5", "", "99999999999"}) {
    expect_serve_rejected({"--max-clients", value}, "--max-clients");
  }
  EXPECT_EQ(run({"serve", "--max-clients", "0"}).cmd.error,
            "cloudsvc serve: --max-clients 0: out of range [1, 1024] (clients)");
  for (const char* value : {"-1", "2.5", "abc", "", "99999999999"}) {
    expect_serve_rejected({"--exit-after-frames", value}, "--exit-after-frames");
  }
  // Permissions must keep the owner's read+write and be octal.
  for (const char* value : {"0400", "0200", "0000", "1777", "0800", "rw", "", "06000"}) {
    expect_serve_rejected({"--socket-mode", value}, "--socket-mode");
    expect_serve_rejected({"--shm", "x", "--shm-mode", value}, "--shm-mode");
  }
  expect_serve_rejected({"--shm-mode", "0600"}, "--shm-mode", "0600");  // without --shm
  for (const char* value : {"-1", "86401", "1.5", "abc", ""}) {
    expect_serve_rejected({"--idle-timeout", value}, "--idle-timeout");
  }
  for (const char* value : {"15", "65537", "abc", ""}) {
    expect_serve_rejected({"--tile-budget", value}, "--tile-budget");
  }
  for (const char* value : {"0x0", "8193x100", "axb"}) {
    expect_serve_rejected({"--max-view-size", value}, "--max-view-size");
  }
  // The initial view must fit the limit clients are held to.
  expect_serve_rejected({"--max-view-size", "320x180", "--size", "640x360"}, "--size", "640x360");
  expect_serve_rejected({"--size", "4000x2000"}, "--size", "4000x2000");
  expect_serve_rejected({"--ready-file", path("no/such/dir/ready")}, "--ready-file");
}

// --ready-file and --out-dir may not take a socket's place: the ready file, renamed into
// place once the sockets were bound, replaced this service's own socket (it said "listening"
// while every connect was refused) or another service's; a directory at the socket's path
// or the ready file's failed only after binding, with exit 1.
TEST_F(CliServeOptionsTest, OutputPathsDoNotClobberTheSockets) {
  const std::string sock = path("s.sock");
  expect_serve_rejected({"--listen", "unix:" + sock, "--ready-file", sock}, "--ready-file", sock);
  expect_serve_rejected({"--listen", "unix:" + sock, "--ready-file", path("sub/../s.sock")}, "--ready-file");
  EXPECT_EQ(run({"serve", "--listen", "unix:" + sock, "--ready-file", sock}).cmd.error,
            "cloudsvc serve: --ready-file " + sock + ": same path as --listen unix:" + sock +
                " (the ready file would replace the socket)");
  const std::string other = path("other.sock");  // another service's socket
  make_socket_file(other);
  expect_serve_rejected({"--ready-file", other}, "--ready-file", other);
  expect_serve_rejected({"--ready-file", dir_.string()}, "--ready-file", dir_.string());
  expect_serve_rejected({"--listen", "unix:" + sock, "--out-dir", sock}, "--out-dir", sock);
  expect_serve_rejected({"--listen", "unix:" + sock, "--out-dir", sock + "/"}, "--out-dir");
  expect_serve_rejected({"--ready-file", path("frames"), "--out-dir", path("frames/")}, "--out-dir");
  EXPECT_FALSE(fs::exists(sock));
  EXPECT_FALSE(fs::exists(path("frames")));
  // Next to each other they are fine.
  const ServeOptions o = serve_with({"--listen", "unix:" + sock, "--ready-file", path("ready"), "--out-dir", path("frames")});
  EXPECT_EQ(o.ready_file, path("ready"));
  EXPECT_EQ(o.out_dir, path("frames"));
}

TEST_F(CliServeOptionsTest, UnknownRepeatedAndStrayArguments) {
  expect_serve_rejected({"--lat", "1"}, "--lat");
  expect_serve_rejected({"--shm", "a", "--shm", "b"}, "--shm", "a b");
  expect_serve_rejected({"--max-clients", "2", "--max-clients", "3"}, "more than once");
  expect_serve_rejected({"--listen", "tcp://127.0.0.1:1", "stray"}, "stray");
  EXPECT_EQ(run({"serve", "--foo"}).cmd.error, "cloudsvc serve: --foo: unknown flag");
}

}  // namespace
}  // namespace cloudsvc
