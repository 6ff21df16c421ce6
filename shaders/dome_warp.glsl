// The domain warp of the cumulus domes' outlines (weather::DomeWarp, weather/cumulus_domes.h)
// on the GPU, relative to a centre point C on the shell: per octave, C / lambda as an integer
// lattice cell and a fraction (computed in double on the CPU), so that the lattice
// coordinates of points near C come out exact in float. Needs gradient_noise.glsl and
// cloud_placement.glsl (placement_project).

const int DOME_WARP_OCTAVES = 5;  // = weather::kDomeWarpOctaves

struct DomeWarpFrame {
  ivec4 cell[DOME_WARP_OCTAVES];     // xyz: floor(C / lambda_o)
  vec4 offset[DOME_WARP_OCTAVES];    // xyz: C / lambda_o - cell; w: 1 / lambda_o (1/m)
  float amplitude[DOME_WARP_OCTAVES]; // amplitude_o (m)
  uvec4 seed[DOME_WARP_OCTAVES];     // xyz: the noise seed of each axis
};

// The warped shell point of C + x (x relative to C, on the shell), relative to C: C + x + w
// projected onto the shell (DomeWarp::warped with its first `octaves` octaves).
vec3 dome_warped(DomeWarpFrame wf, PlacementFrame pf, vec3 x, int octaves) {
  vec3 w = vec3(0.0);
  for (int o = 0; o < min(octaves, DOME_WARP_OCTAVES); ++o) {
    vec3 u = wf.offset[o].xyz + x * wf.offset[o].w;
    ivec3 c = wf.cell[o].xyz;
    w += wf.amplitude[o] * vec3(perlin_noise_at(c, u, wf.seed[o].x), perlin_noise_at(c, u, wf.seed[o].y),
                                perlin_noise_at(c, u, wf.seed[o].z));
  }
  return placement_project(pf, x + w);
}
