// cloudbench_stability: the same sweep as `cloudbench --stability` (bench/stability_command.h).
#include "bench/stability_command.h"

int main(int argc, char** argv) { return cloudsvc::stability_command::run(argc, argv); }
