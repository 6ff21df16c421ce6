// CSV pose logs -> PoseTrack (layout also in docs/FLIGHT_LOGS.md).
//
//   # replay of a test flight (lines whose first non-blank character is '#' are comments)
//   time,lat,lon,alt,heading,pitch,roll
//   2024-05-01T12:00:00Z,47.45,8.56,2500,270,5,0
//   1714564801.5,47.4501,8.5598,2501,270.5,5,2
//
//  - Header row required (the first line that is neither blank nor a comment): column
//    names, ASCII case-insensitive, surrounding spaces ignored, any order; it must name
//    time, lat, lon, alt, heading, pitch and roll once each. Other columns are ignored.
//  - Every row has exactly as many fields as the header. Fields may be quoted RFC 4180
//    style ("a,b", "say ""hi""") with no line breaks inside.
//  - time: ISO 8601 UTC ("2024-05-01T12:00:00Z", "...T12:00:00.25+00:00") or seconds since
//    the Unix epoch (a plain number), per row; years 1900..2199; strictly increasing.
//  - lat, lon: degrees WGS84. lat in [-90, 90] (not wrapped). lon in [-360, 360], wrapped
//    into [-180, 180): a track counted on past +-180 across the antimeridian, or written in
//    the 0..360 convention, reads as it is meant; beyond one turn is an error.
//    alt: metres above the WGS84 ellipsoid, [kMinAltitude_m, kMaxAltitude_m]. heading:
//    true, clockwise from north (wrapped to [0, 360)); pitch: nose up positive, [-90, 90];
//    roll: right wing down positive (wrapped to [-180, 180)); degrees.
//  - velocity_enu_mps is left empty.
#pragma once

#include <string>
#include <string_view>

#include "sim_client/pose_track.h"

namespace cloudsvc::sim {

// Parses the text of a CSV pose log; `source` names it in errors (FlightLogError) and
// becomes PoseTrack::source.
PoseTrack parse_csv(std::string_view text, const std::string& source);

}  // namespace cloudsvc::sim
