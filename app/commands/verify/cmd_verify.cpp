// `silva verify DIR`: a label certificate for a finished dataset, from an independent ray caster.
#include <memory>

#include "app/cli/command_options.hpp"
#include "app/cli/subcommands.hpp"
#include "app/commands/verify/verify_command.hpp"

namespace silva::app {

namespace {

struct VerifyArgs {
  VerifyRequest request;
  std::string dir;
  int threads = 0;
  OutputFlags output;
};

}  // namespace

Handler add_verify_command(CLI::App& root) {
  auto args = std::make_shared<VerifyArgs>();
  CLI::App* cmd = root.add_subcommand(
      "verify",
      "Rebuild the world of a finished dataset from its manifest, cast a ray through the pixel centres of a seeded "
      "choice of frames with the Embree ray caster and compare with the label, depth, normal and LiDAR files; write "
      "DIR/verify.json and DIR/VERIFY.md. Exit 0 when the thresholds are met, 4 when not.");
  cmd->add_option("DIR", args->dir, "the dataset folder <output.dir>/<seed>/")->required();
  cmd->add_option("--frames", args->request.frames,
                  "frames to check: one seeded frame from each of N equal parts of the frame list (default 8; all "
                  "when the dataset has fewer)")
      ->check(CLI::Range(1, 1'000'000))
      ->type_name("N");
  cmd->add_option("--sample", args->request.sample,
                  "share of each frame's pixels cast, seeded per pixel (default 0.25; 1 = every pixel)")
      ->check(finite_range(1e-6, 1.0))
      ->type_name("F");
  cmd->add_option("--min-class", args->request.min_class,
                  "percent of interior pixels whose class must agree (default 99.9)")
      ->check(finite_range(0.0, 100.0))
      ->type_name("PCT");
  cmd->add_option("--min-depth", args->request.min_depth,
                  "percent of hit pixels whose depth must agree within --depth-tolerance (default 99.9)")
      ->check(finite_range(0.0, 100.0))
      ->type_name("PCT");
  cmd->add_option("--depth-tolerance", args->request.depth_tolerance,
                  "relative depth error, percent, that still agrees (default 0.1)")
      ->check(finite_range(0.0, 100.0))
      ->type_name("PCT");
  cmd->add_flag("--full-detail", args->request.full_detail,
                "cast every instance at full detail even when the dataset was rendered with render.lod = true "
                "(default: at the level the rasteriser drew for each frame); measures how far LOD moves depth");
  add_threads_option(*cmd, args->threads);
  add_output_flags(*cmd, args->output);
  cmd->footer("Examples:\n  silva verify out/1234567890\n  silva verify out/1234567890 --frames 30 --sample 1 --json");
  return [args] {
    const Reporter reporter(args->output);
    const ThreadLimit limit(args->threads);
    args->request.run_dir = args->dir;
    return run_verify(args->request, reporter);
  };
}

}  // namespace silva::app
