#!/usr/bin/env bash
# The optics gallery (docs/GALLERY.md): the glory, the fogbow, snow vs sea under a stratus
# deck and a sunset deck, each rendered by the GPU (default preset; Jendersie-d'Eon fit and
# Lorenz-Mie phase) next to the path-traced truth of the same view (`--quality truth`).
#
#   bash scripts/gallery.sh                                  # needs build/bin/cloudsvc
#   GALLERY_SIZE=96 GALLERY_SPP=256 GALLERY_ZOOM=3 bash scripts/gallery.sh
#                      # square image size, truth paths per pixel, PNG enlargement
#
# Every image of a row is shown with the same exposure, from the row's truth: PNG =
# sRGB(x / (1 + x)), x = radiance / (mean radiance of the truth image), so brightness
# differences between the columns are the renderers', not an auto-exposure's; under each
# image its mean radiance (green) over the truth's. Writes docs/img/gallery/*.png and
# docs/GALLERY.md (the table, the command, the numbers); the linear EXR renders go to a
# temporary directory.
set -euo pipefail
cd "$(dirname "$0")/.."
out=docs/img/gallery  # docs/GALLERY.md links the images there
size="${GALLERY_SIZE:-96}"
spp="${GALLERY_SPP:-256}"
zoom="${GALLERY_ZOOM:-3}"  # the PNGs are enlarged this many times, pixels kept square
bin=build/bin/cloudsvc
[ -x "$bin" ] || { echo "gallery: $bin not built (bash scripts/build.sh)" >&2; exit 1; }
command -v oiiotool >/dev/null || { echo "gallery: oiiotool missing (bash scripts/install-deps.sh)" >&2; exit 1; }
mkdir -p "$out"
work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT

# Weather: an overcast stratus deck 400-900 m, 10 um droplets, over land, snow or sea.
deck() {  # $1 = file, $2 = ground albedo JSON fragment (may be empty)
  cat > "$1" <<EOF
{"name": "stratus deck", "map_seed": 3, $2
 "layers": [{"type": "stratus", "base_m": 400, "top_m": 900, "coverage": 1.0, "droplet_diameter_um": 10}]}
EOF
}
deck "$work/deck.json" ""
deck "$work/snow.json" '"ground_albedo": 0.8,'
deck "$work/sea.json" '"ground_albedo": 0.1,'

place=(--lat 47.45 --lon 8.56)
morning="2026-06-21T10:00:00Z"
# The antisolar direction from 2 km at that time: the sun's azimuth and elevation from a 1x1 render.
line="$($bin render "${place[@]}" --alt 2000 --time "$morning" --size 1x1 --weather "$work/deck.json" --out "$work/sun.exr")"
sun_el="$(sed -n 's/.*sun elevation \([-0-9.]*\) deg azimuth \([-0-9.]*\) deg.*/\1/p' <<<"$line")"
sun_az="$(sed -n 's/.*sun elevation \([-0-9.]*\) deg azimuth \([-0-9.]*\) deg.*/\2/p' <<<"$line")"
anti_heading="$(awk -v a="$sun_az" 'BEGIN { h = a + 180; if (h >= 360) h -= 360; printf "%.3f", h }')"
anti_pitch="$(awk -v e="$sun_el" 'BEGIN { printf "%.3f", -e }')"

rows=()   # "name|caption|view flags|weather|columns (space-separated kind:label)"
rows+=("glory|From 2 km above the deck towards the antisolar point, 16° across (sun ${sun_el}° high): the glory's coloured rings, ~3–4° for 10 µm droplets|--alt 2000 --time $morning --heading $anti_heading --pitch $anti_pitch --fov 16|deck|fit mie truth-mie")
rows+=("fogbow|The same point, 100° across: the fogbow ~37° from it|--alt 2000 --time $morning --heading $anti_heading --pitch $anti_pitch --fov 100|deck|fit mie truth-mie")
rows+=("snow|From 100 m under the deck over snow (albedo 0.8), level, 90° across: the light between ground and cloud base|--alt 100 --time $morning --heading 90 --pitch 0 --fov 90|snow|fit truth-fit")
rows+=("sea|The same view over sea (albedo 0.1), shown with the snow row's exposure|--alt 100 --time $morning --heading 90 --pitch 0 --fov 90|sea|fit truth-fit")
rows+=("sunset|Above the stratocumulus-deck preset at sunset (sun 2° high) from 3 km, looking away from the sun at the lit tops and their long shadows|--alt 3000 --time 2026-06-21T19:05:00Z --heading 120 --pitch -12 --fov 75|stratocumulus-deck|fit mie truth-fit")

render() {  # $1 = output exr, $2 = kind, then the view flags and --weather
  local file="$1" kind="$2"
  shift 2
  local extra=()
  case "$kind" in
    fit) extra=(--quality default --frames 17) ;;
    mie) extra=(--quality default --frames 17 --cloud-phase mie) ;;
    truth-fit) extra=(--quality truth --spp "$spp") ;;
    truth-mie) extra=(--quality truth --spp "$spp" --cloud-phase mie) ;;
  esac
  "$bin" render "${place[@]}" "$@" --size "${size}x${size}" "${extra[@]}" --out "$file" > "$work/render.log" ||
    { echo "gallery: render of $file failed:" >&2; cat "$work/render.log" >&2; exit 1; }
}

# mean green radiance of an EXR (oiiotool --stats: "Stats Avg: r g b a")
mean_green() { oiiotool --stats "$1" | sed -n 's/.*Stats Avg: *\([^ ]*\) \([^ ]*\) .*/\2/p' | head -1; }

to_png() {  # $1 = exr, $2 = png, $3 = scale
  oiiotool "$1" --ch R,G,B --mulc "$3" --dup --addc 1 --div --colorconvert linear sRGB \
    --resize:filter=box "$((size * zoom))x$((size * zoom))" -d uint8 -o "$2"
}

md="docs/GALLERY.md"
{
  echo "# Optics gallery"
  echo
  echo "The GPU renderer (default preset, the view held still for 17 frames) with the Jendersie–d'Eon"
  echo "phase fit (\`fit\`) and with the droplets' Lorenz–Mie phase function (\`mie\`, docs/RENDERING.md),"
  echo "next to the path-traced ground truth of the same view (docs/TRUTH.md: every order of"
  echo "scattering, ${spp} paths per pixel). Each row is shown with one exposure, set by its truth"
  echo "(x / (1 + x) of radiance over the truth's mean, sRGB), so what differs between columns is"
  echo "the renderers. Place 47.45 N 8.56 E, 2026-06-21; ${size}×${size} pixels (shown ${zoom}× enlarged); the weather is an"
  echo "overcast stratus deck 400–900 m with 10 µm droplets unless named."
  echo
  echo "Command: \`GALLERY_SIZE=${size} GALLERY_SPP=${spp} GALLERY_ZOOM=${zoom} bash scripts/gallery.sh\` ($(date -u +%Y-%m-%d), 2 cores, llvmpipe);"
  echo "under each image: its mean radiance (550 nm) over the truth's."
  echo
  echo "What to look for. The glory's rings and the fogbow are a few per cent of the deck's"
  echo "radiance, so at this exposure they are faint in the GPU's Mie column and, at this path"
  echo "count, below the truth's per-pixel noise; where Mie puts them, and where the GPU image"
  echo 'has them, is measured in docs/ACCURACY.md §4 (`build/bin/render_mie_phase_test`), and the'
  echo "truth's Mie single scattering against the closed form in docs/TRUTH.md. The ratios are"
  echo "the light model's error (docs/RENDERING.md, \"Light\"): on homogeneous slabs it is within"
  echo "a factor 1.03–1.06 of Monte Carlo (docs/ACCURACY.md §4); under a deck, the ground seen"
  echo "straight down and the deck's base straight up are within 5 % of the truth"
  echo "(docs/ACCURACY.md, ground–cloud inter-reflection). The level views under the deck"
  echo "below look through its textured base at grazing angles, where the light model reads"
  echo "the deck as slabs of its nominal depth (docs/ACCURACY.md §0)."
  echo
} > "$md"

snow_scale=""
for row in "${rows[@]}"; do
  IFS='|' read -r name caption view weather columns <<<"$row"
  wflag="$weather"
  [ -f "$work/$weather.json" ] && wflag="$work/$weather.json"
  read -r -a view_flags <<<"$view"
  truth_file=""
  for kind in $columns; do
    render "$work/$name-$kind.exr" "$kind" "${view_flags[@]}" --weather "$wflag"
    case "$kind" in truth-*) truth_file="$work/$name-$kind.exr" ;; esac
    echo "gallery: $name $kind" >&2
  done
  mean="$(mean_green "$truth_file")"
  scale="$(awk -v m="$mean" 'BEGIN { printf "%.6g", (m > 0 ? 1 / m : 1) }')"
  if [ "$name" = snow ]; then snow_scale="$scale"; fi
  if [ "$name" = sea ] && [ -n "$snow_scale" ]; then scale="$snow_scale"; fi
  {
    echo "**${caption}.**"
    echo
    header="|" rule="|" images="|" ratios="|"
    for k in $columns; do
      to_png "$work/$name-$k.exr" "$out/$name-$k.png" "$scale"
      ratio="$(awk -v a="$(mean_green "$work/$name-$k.exr")" -v m="$mean" 'BEGIN { printf "%.3f", a / m }')"
      case "$k" in
        fit) label="GPU, fit" ;; mie) label="GPU, Mie" ;; truth-fit) label="truth, fit" ;; truth-mie) label="truth, Mie" ;;
      esac
      header+=" ${label} |"
      rule+="---|"
      images+=" ![${name} ${label}](img/gallery/${name}-${k}.png) |"
      ratios+=" ${ratio} × truth |"
    done
    echo "$header"; echo "$rule"; echo "$images"; echo "$ratios"
    echo
  } >> "$md"
done
echo "gallery: wrote $md and $out/" >&2
