// Soak report: JSON and key=value lines from one ordered JSON object (soak_summary.h).
#include "sim_client/soak_summary.h"

#include <cstdio>
#include <set>

#include "sim_client/run_summary.h"

namespace cloudsvc::sim {

namespace {

using Json = nlohmann::ordered_json;

Json distribution(const std::vector<double>& values) {
  const Distribution d = summarize(values);
  return Json{{"p50", d.median}, {"p95", d.p95}, {"max", d.max}, {"count", d.count}};
}

std::vector<double> joined(const SoakSummary& s, std::vector<double> SoakClientStats::*member) {
  std::vector<double> all;
  for (const SoakClientStats& c : s.clients) all.insert(all.end(), (c.*member).begin(), (c.*member).end());
  return all;
}

std::uint64_t error_count(const SoakClientStats& c) {
  std::uint64_t n = 0;
  for (const auto& [code, k] : c.errors) n += k;
  return n;
}

// A Stats counter's growth over the run (0 when either end is missing).
std::uint64_t delta(const SoakSummary& s, std::uint64_t protocol::Stats::*counter) {
  if (!s.service_start || !s.service_end) return 0;
  const std::uint64_t a = (*s.service_start).*counter, b = (*s.service_end).*counter;
  return b >= a ? b - a : 0;
}

std::string real_text(double v) {
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.3f", v);
  return buf;
}

void flatten(const Json& j, const std::string& prefix, std::string& out) {
  if (j.is_object() || j.is_array()) {
    std::size_t i = 0;
    for (auto it = j.begin(); it != j.end(); ++it, ++i) {
      const std::string key = j.is_object() ? it.key() : std::to_string(i);
      flatten(*it, prefix.empty() ? key : prefix + "." + key, out);
    }
    return;
  }
  out += prefix + "=";
  if (j.is_string()) out += j.get<std::string>();
  else if (j.is_number_float()) out += real_text(j.get<double>());
  else out += j.dump();
  out += "\n";
}

std::string number_text(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%g", v);
  return buf;
}

}  // namespace

Json soak_report(const SoakSummary& s, bool errors_expected) {
  std::uint64_t poses = 0, skipped = 0, requests = 0, frames = 0, own = 0, request_frames = 0, disconnects = 0,
                drain_timeouts = 0;
  std::map<std::string, std::uint64_t> errors;
  std::set<std::uint64_t> distinct;
  for (const SoakClientStats& c : s.clients) {
    poses += c.poses_sent;
    skipped += c.poses_skipped;
    requests += c.requests_sent;
    frames += c.frames;
    own += c.own_frames;
    request_frames += c.request_frames;
    disconnects += c.disconnected;
    drain_timeouts += !c.disconnected && !c.final_stats;
    for (const auto& [code, n] : c.errors) errors[code] += n;
    distinct.insert(c.frame_numbers.begin(), c.frame_numbers.end());
  }
  std::string connect;
  for (const std::string& a : s.addresses) connect += (connect.empty() ? "" : ",") + a;

  Json r;
  r["clients"] = s.clients.size();
  r["rate_hz"] = s.rate_hz;
  r["duration_s"] = s.duration_s;
  r["warm_up_s"] = s.warm_up_s;
  r["run_s"] = s.run_s;
  r["connect"] = connect;
  r["view"] = s.view_sent ? std::to_string(s.width) + "x" + std::to_string(s.height) : std::string("service");
  r["render_every"] = s.render_every;
  r["threads"] = s.threads;
  r["poses_sent"] = poses;
  r["poses_skipped"] = skipped;
  r["requests_sent"] = requests;
  r["frames_received"] = frames;
  r["frames_distinct"] = distinct.size();
  r["frame_rate_hz"] = s.run_s > 0.0 ? static_cast<double>(distinct.size()) / s.run_s : 0.0;
  r["own_frames"] = own;
  r["latency_ms"] = distribution(joined(s, &SoakClientStats::latency_ms));
  r["service_latency_ms"] = distribution(joined(s, &SoakClientStats::service_latency_ms));
  if (s.render_every > 0) {
    r["request_frames"] = request_frames;
    r["request_latency_ms"] = distribution(joined(s, &SoakClientStats::request_latency_ms));
  }
  Json e;
  std::uint64_t total_errors = 0;
  for (const auto& [code, n] : errors) total_errors += n;
  e["total"] = total_errors;
  for (const auto& [code, n] : errors) e[code] = n;
  r["errors"] = e;
  r["disconnects"] = disconnects;
  r["drain_timeouts"] = drain_timeouts;
  r["service"] = Json{{"frames_rendered", delta(s, &protocol::Stats::frames_rendered)},
                      {"poses_received", delta(s, &protocol::Stats::poses_received)},
                      {"poses_dropped", delta(s, &protocol::Stats::poses_dropped)}};
  if (s.service_pid > 0) {
    r["service_pid"] = s.service_pid;
    r["rss_kib"] = Json{{"start", s.rss.start / 1024}, {"max", s.rss.max / 1024}, {"end", s.rss.end / 1024},
                        {"samples", s.rss.samples}};
    r["service_gone"] = s.service_gone;
  }
  Json per = Json::array();
  for (const SoakClientStats& c : s.clients) {
    Json j{{"address", c.address},          {"poses_sent", c.poses_sent}, {"frames", c.frames},
           {"own_frames", c.own_frames},    {"errors", error_count(c)},   {"disconnected", c.disconnected}};
    if (c.disconnected) j["reason"] = c.disconnect_reason;
    per.push_back(j);
  }
  r["per_client"] = per;
  std::string result;
  for (const std::string& why : soak_failures(s, errors_expected)) result += (result.empty() ? "failed: " : "; ") + why;
  r["result"] = result.empty() ? "ok" : result;
  return r;
}

std::string format_soak_report(const SoakSummary& s, bool errors_expected) {
  std::string connect;
  for (const std::string& a : s.addresses) connect += (connect.empty() ? "" : ", ") + a;
  std::string out = "soak: " + std::to_string(s.clients.size()) + " clients x " + number_text(s.rate_hz) +
                    " Hz for " + number_text(s.duration_s) + " s (" + connect + "), view " +
                    (s.view_sent ? std::to_string(s.width) + "x" + std::to_string(s.height) : "of the service") +
                    "\n";
  flatten(soak_report(s, errors_expected), "", out);
  return out;
}

std::vector<std::string> soak_failures(const SoakSummary& s, bool errors_expected) {
  std::vector<std::string> why;
  std::uint64_t frames = 0, errors = 0;
  std::size_t disconnected = 0, unanswered = 0;
  for (const SoakClientStats& c : s.clients) {
    frames += c.frames;
    errors += error_count(c);
    disconnected += c.disconnected;
    unanswered += !c.disconnected && !c.final_stats;
  }
  if (disconnected) why.push_back(std::to_string(disconnected) + " client(s) disconnected");
  if (unanswered) why.push_back(std::to_string(unanswered) + " final StatsRequest(s) unanswered");
  if (s.service_gone) why.push_back("the service process (pid " + std::to_string(s.service_pid) + ") went away");
  if (frames == 0) why.push_back("no frame received");
  if (errors && !errors_expected) why.push_back(std::to_string(errors) + " Error(s) received");
  return why;
}

}  // namespace cloudsvc::sim
