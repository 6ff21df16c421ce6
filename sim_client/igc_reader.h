// IGC flight recorder files (FAI/IGC "Technical specification for IGC-approved GNSS flight
// recorders", Appendix A) -> PoseTrack.
//
// Read:
//  - A record: must be the first record (else "missing A record": not an IGC file).
//  - HFDTE date, both forms: "HFDTEDDMMYY" (before 2016) and "HFDTEDATE:DDMMYY,NN"; any
//    H source letter (HF/HO/HP) is accepted, the first date record wins. Two-digit years:
//    80..99 -> 19xx, 00..79 -> 20xx. The date is the UTC date of the first fix.
//  - B records, fixed columns (0-based byte offsets):
//      [1,7) HHMMSS UTC   [7,15) DDMMmmm N/S   [15,24) DDDMMmmm E/W   [24] validity A/V
//      [25,30) pressure altitude (m, ISA 1013.25 hPa)   [30,35) GNSS altitude (m)
//    Latitude degrees 00..90 (at most 90 00.000'). Longitude degrees 000..180; 180 with
//    non-zero minutes (a recorder counting on past the antimeridian) is the point that
//    many minutes past it on the other side and is wrapped there; every longitude is
//    returned in [-180, 180) (180 00.000'E is -180).
//    Bytes after 35 are the extensions declared by the I record (FXA, ENL, LAD/LOD, ...):
//    they are ignored, so unknown or malformed I records never matter.
//  - All other records (C, D, E, F, G, J, K, L, H other than the date) are ignored.
// Altitude: the GNSS altitude, taken as height above the WGS84 ellipsoid (what the IGC
// specification says; some recorders declare HFALG:GEO, i.e. above the geoid, a difference
// of |N| < 110 m that is not corrected). A fix whose GNSS altitude is invalid (validity V:
// 2D or no fix) or exactly 0 (many recorders write 00000 when they have no 3D solution or
// clip negative heights) falls back to the pressure altitude plus the median
// (GNSS - pressure) offset over the fixes where both are valid and non-zero (0 when there
// are none), so the switch does not make the track jump by the ISA/QNH and geoid offset.
// A V fix at exactly 0 N 0 E (no position yet) is skipped.
// Time: day of HFDTE + HHMMSS; when the time of day decreases by more than 12 h the day is
// incremented (flight past midnight UTC). A fix at the same time as the previous kept fix
// is skipped (recorders repeat fixes). A smaller decrease is "time goes backwards": an
// error, or with skip_out_of_order the fix is dropped.
// Attitude: IGC has none; heading, pitch and bank (and velocity_enu_mps) are derived from
// the track by derive_attitude_from_track (method and limits in track_attitude.h).
#pragma once

#include <string>
#include <string_view>

#include "sim_client/pose_track.h"
#include "sim_client/track_attitude.h"

namespace cloudsvc::sim {

struct IgcOptions {
  // Drop fixes whose time goes backwards (not a midnight wrap) instead of failing.
  bool skip_out_of_order = false;
  DerivedAttitudeParams attitude;
};

// Parses the text of an IGC file; `source` names it in errors (FlightLogError,
// "<source>:<line>: <problem>") and becomes PoseTrack::source.
PoseTrack parse_igc(std::string_view text, const std::string& source,
                    const IgcOptions& options = {});

}  // namespace cloudsvc::sim
