// ACMI reader: two passes over the record stream. Pass 1 collects the globals and which
// objects exist (with their Names); the object is chosen; pass 2 builds its track.
#include "sim_client/acmi_reader.h"

#include <algorithm>
#include <map>
#include <optional>
#include <vector>

#include "geodesy/utc_time.h"
#include "sim_client/acmi_lexer.h"
#include "sim_client/acmi_transform.h"
#include "sim_client/angles.h"
#include "sim_client/flight_log_error.h"
#include "sim_client/text_input.h"
#include "sim_client/value_checks.h"

namespace cloudsvc::sim {

namespace {

using acmi::Record;

struct ObjectInfo {
  std::vector<std::string> names;  // every distinct Name, in order of appearance
  bool has_position = false;       // at least one T=
};

struct Globals {
  std::optional<std::string> reference_time;
  std::size_t reference_time_line = 0;
  double reference_lon_deg = 0.0;
  double reference_lat_deg = 0.0;
  std::size_t first_timed_line = 0;  // first object record: where a time is first needed
};

class AcmiParser {
 public:
  AcmiParser(std::string_view text, const std::string& source, const AcmiOptions& options)
      : text_(text), source_(source), options_(options) {}

  PoseTrack run() {
    acmi::lex_acmi(text_, source_, [this](const Record& r) { collect(r); });
    const double reference_time = resolve_reference_time();
    id_ = choose_object();
    acmi::lex_acmi(text_, source_, [this](const Record& r) { follow(r); });
    return build_track(reference_time);
  }

 private:
  [[noreturn]] void fail(std::size_t line, const std::string& problem) const {
    throw FlightLogError(source_, line, problem);
  }

  double global_number(const Record& r, const std::string& key, const std::string& value) const {
    const std::optional<double> v = parse_number(value);
    if (!v) fail(r.line, "malformed " + key + " " + quoted_excerpt(value));
    if (auto p = finite_problem(key, *v)) fail(r.line, *p);
    return *v;
  }

  // Pass 1: globals, object names, syntax of every T=.
  void collect(const Record& r) {
    if (r.kind == Record::Kind::object_removal) return;
    if (r.id == 0) {
      for (const acmi::Property& p : r.properties) {
        if (p.key == "ReferenceTime") {
          globals_.reference_time = p.value;
          globals_.reference_time_line = r.line;
        } else if (p.key == "ReferenceLongitude") {
          globals_.reference_lon_deg = global_number(r, p.key, p.value);
        } else if (p.key == "ReferenceLatitude") {
          globals_.reference_lat_deg = global_number(r, p.key, p.value);
        }
      }
      return;
    }
    if (globals_.first_timed_line == 0) globals_.first_timed_line = r.line;
    ObjectInfo& info = objects_[r.id];
    for (const acmi::Property& p : r.properties) {
      if (p.key == "T") {
        acmi::parse_transform(p.value, source_, r.line);  // syntax check of every object
        info.has_position = true;
      } else if (p.key == "Name") {
        if (std::find(info.names.begin(), info.names.end(), p.value) == info.names.end())
          info.names.push_back(p.value);
      }
    }
  }

  double resolve_reference_time() const {
    if (!globals_.reference_time)
      fail(globals_.first_timed_line != 0 ? globals_.first_timed_line : 1,
           "missing global 0,ReferenceTime=<ISO 8601 UTC> (needed for absolute times)");
    const std::optional<double> t = geo::parse_utc_iso8601(*globals_.reference_time);
    if (!t)
      fail(globals_.reference_time_line,
           "ReferenceTime " + quoted_excerpt(*globals_.reference_time) +
               " is not an ISO 8601 UTC time");
    return *t;
  }

  std::string describe(std::uint64_t id) const {
    std::string s = acmi::format_object_id(id);
    const auto it = objects_.find(id);
    if (it != objects_.end() && !it->second.names.empty())
      s += " (" + it->second.names.front() + ")";
    return s;
  }

  // "1 (E-3A), 2 (E-3A), 3" for the objects with a position (at most 12 listed).
  std::string positioned_objects() const {
    std::string list;
    std::size_t n = 0;
    for (const auto& [id, info] : objects_) {
      if (id == 0 || !info.has_position) continue;
      if (n == 12) return list + ", ...";
      list += (n++ ? ", " : "") + describe(id);
    }
    return n ? list : "none";
  }

  std::uint64_t choose_object() const {
    const std::string& want = options_.object;
    if (want.empty()) {
      std::vector<std::uint64_t> candidates;
      for (const auto& [id, info] : objects_)
        if (id != 0 && info.has_position) candidates.push_back(id);
      if (candidates.size() == 1) return candidates.front();
      if (candidates.empty()) fail(0, "no object with a position (T=): empty track");
      fail(0, std::to_string(candidates.size()) +
                  " objects have positions; choose one by hex id or Name: " +
                  positioned_objects());
    }
    std::uint64_t id = 0;
    if (acmi::parse_object_id(want, id) && id != 0 && objects_.count(id))
      return require_position(id);
    std::vector<std::uint64_t> named;
    for (const auto& [oid, info] : objects_)
      for (const std::string& name : info.names)
        if (oid != 0 && iequals(name, want)) {
          named.push_back(oid);
          break;
        }
    if (named.size() == 1) return require_position(named.front());
    if (named.empty())
      fail(0, "unknown object " + quoted_excerpt(want) +
                  ": no object has that hex id or Name; objects with positions: " +
                  positioned_objects());
    std::string ids;
    for (std::uint64_t n : named) ids += (ids.empty() ? "" : ", ") + acmi::format_object_id(n);
    fail(0, "object name " + quoted_excerpt(want) + " is ambiguous: objects " + ids +
                " have it; choose one by hex id");
  }

  std::uint64_t require_position(std::uint64_t id) const {
    if (!objects_.at(id).has_position)
      fail(0, "object " + describe(id) + " has no position (T=): empty track");
    return id;
  }

  // Pass 2: the chosen object's samples.
  void follow(const Record& r) {
    if (r.id != id_ || removed_) return;
    if (r.kind == Record::Kind::object_removal) {
      removed_ = true;
      return;
    }
    for (const acmi::Property& p : r.properties)
      if (p.key == "T") apply(r, acmi::parse_transform(p.value, source_, r.line));
  }

  void apply(const Record& r, const acmi::Transform& t) {
    if (t.lon_deg) lon_ = globals_.reference_lon_deg + *t.lon_deg;
    if (t.lat_deg) lat_ = globals_.reference_lat_deg + *t.lat_deg;
    if (t.alt_m) alt_ = *t.alt_m;
    if (t.roll_deg) roll_ = *t.roll_deg;
    if (t.pitch_deg) pitch_ = *t.pitch_deg;
    if (t.yaw_deg) yaw_ = *t.yaw_deg;
    if (t.field_count == 6 || t.field_count == 9) oriented_ = true;
    if (!lon_ || !lat_ || !alt_)
      fail(r.line, "first T= of object " + describe(id_) +
                       " leaves longitude, latitude or altitude empty");
    if (auto p = range_problem("latitude", *lat_, -90.0, 90.0)) fail(r.line, *p);
    // Longitudes are ReferenceLongitude + offset, which runs past +-180 on a flight across
    // the antimeridian (Tacview itself wraps them): any finite sum is a longitude.
    if (auto p = finite_problem("longitude", *lon_)) fail(r.line, *p);
    if (auto p = range_problem("altitude", *alt_, kMinAltitude_m, kMaxAltitude_m))
      fail(r.line, *p);
    if (auto p = range_problem("pitch", pitch_, -90.0, 90.0)) fail(r.line, *p);

    PoseSample s;
    s.unix_time_s = r.time_s;  // relative until build_track
    s.position = {*lat_, wrap_lon_deg(*lon_), *alt_};
    s.attitude = {wrap_deg_360(yaw_), pitch_, wrap_deg_180(roll_)};
    if (!samples_.empty() && samples_.back().unix_time_s == r.time_s) {
      samples_.back() = s;  // several T= in one frame: the last wins
      oriented_flags_.back() = oriented_;
      sample_lines_.back() = r.line;
    } else {
      samples_.push_back(s);
      oriented_flags_.push_back(oriented_);
      sample_lines_.push_back(r.line);
    }
  }

  PoseTrack build_track(double reference_time) {
    if (samples_.empty())  // its only T= records follow its removal
      fail(0, "object " + describe(id_) + " has no position before its removal: empty track");
    PoseTrack track;
    track.source = source_ + " object " + describe(id_);
    // Absolute times; frames closer than the resolution of the sum (~0.2 us in 2020) merge
    // into the later one so the track stays strictly increasing.
    std::vector<bool> oriented;
    for (std::size_t i = 0; i < samples_.size(); ++i) {
      PoseSample s = samples_[i];
      s.unix_time_s += reference_time;
      // A frame time (#seconds, any finite value) can carry the sample out of the years a
      // pose may have; said here, at its line, not as a pose the replay cannot send.
      if (!(s.unix_time_s >= kMinUnixTime && s.unix_time_s < kEndUnixTime))
        fail(sample_lines_[i], "frame time #" + format_number(samples_[i].unix_time_s) + " after ReferenceTime " +
                                   quoted_excerpt(*globals_.reference_time) +
                                   " is out of range: sample times must be in years 1900-2199");
      if (!track.samples.empty() && s.unix_time_s <= track.samples.back().unix_time_s) {
        track.samples.back() = s;
        oriented.back() = oriented_flags_[i];
      } else {
        track.samples.push_back(s);
        oriented.push_back(oriented_flags_[i]);
      }
    }
    std::vector<geo::Attitude> given;
    for (const PoseSample& s : track.samples) given.push_back(s.attitude);
    derive_attitude_from_track(track.samples, options_.attitude);
    for (std::size_t i = 0; i < track.samples.size(); ++i)
      if (oriented[i]) track.samples[i].attitude = given[i];
    return track;
  }

  std::string_view text_;
  const std::string& source_;
  const AcmiOptions& options_;
  Globals globals_;
  std::map<std::uint64_t, ObjectInfo> objects_;

  std::uint64_t id_ = 0;  // chosen object
  bool removed_ = false;
  std::optional<double> lon_, lat_, alt_;
  double roll_ = 0.0, pitch_ = 0.0, yaw_ = 0.0;
  bool oriented_ = false;
  std::vector<PoseSample> samples_;
  std::vector<bool> oriented_flags_;
  std::vector<std::size_t> sample_lines_;  // the line of each sample's (last) T=
};

}  // namespace

PoseTrack parse_acmi(std::string_view text, const std::string& source, const AcmiOptions& options) {
  return AcmiParser(text, source, options).run();
}

}  // namespace cloudsvc::sim
