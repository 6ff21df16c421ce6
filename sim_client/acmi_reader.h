// Tacview ACMI 2.1 / 2.2 text recordings -> PoseTrack of one object.
//
// Syntax and T= forms: acmi_lexer.h, acmi_transform.h. The reader
//  - needs the global (object 0) ReferenceTime (ISO 8601 UTC): sample times are
//    ReferenceTime + the "#<seconds>" frame time; ReferenceLongitude/ReferenceLatitude
//    (default 0) are added to every T= longitude/latitude;
//  - picks one object (AcmiOptions::object): a hex id present in the file ("3000102",
//    "0x3000102") or else a Name (ASCII case-insensitive; any Name the object had). With
//    no choice the file must hold exactly one object with a position. Unknown, ambiguous
//    (a Name shared by several objects) or position-less objects are errors at line 0;
//  - makes one sample per T= of that object (several in one frame merge into the last),
//    until the object's removal ("-<id>"); a later reuse of the id is not followed;
//  - takes altitude as written: ACMI altitudes are metres above mean sea level and are
//    used as heights above the WGS84 ellipsoid (geoid undulation |N| < 110 m, not applied);
//  - takes Roll/Pitch/Yaw as roll/pitch/heading. Samples recorded without orientation (an
//    object written with the 3- or 5-field forms only) get the attitude derived from the
//    track (track_attitude.h). velocity_enu_mps is always derived from the track.
// Checked for the chosen object, after the reference is added: latitude in [-90, 90]
// (not wrapped: past a pole is an error), longitude finite and wrapped into [-180, 180)
// (Tacview coordinates are reference + offset and run past +-180 on a flight across the
// antimeridian), altitude in [kMinAltitude_m, kMaxAltitude_m], pitch in [-90, 90].
#pragma once

#include <string>
#include <string_view>

#include "sim_client/pose_track.h"
#include "sim_client/track_attitude.h"

namespace cloudsvc::sim {

struct AcmiOptions {
  std::string object;  // hex id or Name; empty: the only object with a position
  DerivedAttitudeParams attitude;
};

// Parses the text of an ACMI file; `source` names it in errors (FlightLogError) and starts
// PoseTrack::source ("<source> object <hexid> (<Name>)").
PoseTrack parse_acmi(std::string_view text, const std::string& source,
                     const AcmiOptions& options = {});

}  // namespace cloudsvc::sim
