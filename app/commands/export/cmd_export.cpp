// `silva export DIR --format F`: convert a finished dataset into the formats other tools load.
#include <memory>
#include <sstream>

#include "app/cli/command_options.hpp"
#include "app/cli/subcommands.hpp"
#include "app/commands/export/export_command.hpp"
#include "core/error.hpp"
#include "io/export_formats.hpp"

namespace silva::app {

namespace {

struct ExportArgs {
  std::string dir;
  std::vector<std::string> formats;
  std::string out;
  bool overwrite = false;
  bool copy = false;
  int64_t min_area = io::ExportOptions::kDefaultMinInstanceArea;
  std::string image_format = "png";
  std::string split = "train";
  int threads = 0;
  OutputFlags output;
};

int export_command(const ExportArgs& args) {
  const Reporter reporter(args.output);
  ExportRequest request;
  request.run_dir = args.dir;
  for (const std::string& list : args.formats) {
    std::stringstream names(list);
    for (std::string name; std::getline(names, name, ',');) {
      if (name == "all") {
        request.all = true;
        continue;
      }
      request.formats.push_back(io::parse_export_format(name, "--format '" + list + "'"));
    }
  }
  if (!request.all && request.formats.empty()) throw InputError("--format '" + args.formats.back() + "': names no format");
  request.out_dir = args.out.empty() ? request.run_dir / "export" : std::filesystem::path(args.out);
  request.overwrite = args.overwrite;
  request.options.copy_files = args.copy;
  request.options.min_instance_area = args.min_area;
  request.options.jpeg_images = args.image_format == "jpg";
  request.options.cityscapes_split = args.split;
  const ThreadLimit limit(args.threads);
  return run_export(request, reporter);
}

}  // namespace

Handler add_export_command(CLI::App& root) {
  auto args = std::make_shared<ExportArgs>();
  CLI::App* cmd = root.add_subcommand(
      "export",
      "Convert a finished dataset (no re-rendering) into coco-panoptic, coco-instances, cityscapes, colmap, "
      "nerfstudio, semantickitti (LiDAR), rosbag2 (a ROS 2 bag per sequence, MCAP) or euroc (the trajectory "
      "sequence with its IMU, as visual-inertial odometry reads it), each into "
      "<out>/<format>/; the dataset's images and scans are hard-linked (editing one in place edits the dataset "
      "too) unless --copy.");
  cmd->add_option("DIR", args->dir, "the dataset folder <output.dir>/<seed>/")->required();
  cmd->add_option("--format", args->formats,
                  "coco-panoptic, coco-instances, cityscapes, colmap, nerfstudio, semantickitti, rosbag2, euroc, or "
                  "all (every camera format and rosbag2, semantickitti when the dataset has lidar, euroc when it has "
                  "the trajectory sequence; several: comma-separated)")
      ->required()
      ->type_name("F");
  cmd->add_option("--out", args->out, "folder that receives one sub-folder per format (default DIR/export)")
      ->type_name("DIR");
  cmd->add_flag("--overwrite", args->overwrite, "replace an existing <out>/<format>/");
  cmd->add_flag("--copy", args->copy,
                "copy the dataset's images and scans into the export instead of hard-linking them, so that editing "
                "the export never edits the dataset (uses their disk space again)");
  cmd->add_option("--min-area", args->min_area,
                  "instances covering fewer pixels of a frame are iscrowd 1 in coco-instances and coco-panoptic "
                  "(fragments a detector should neither learn nor be scored on); 0 marks none")
      ->check(CLI::Range(int64_t(0), int64_t(1) << 30))
      ->default_val(io::ExportOptions::kDefaultMinInstanceArea)
      ->type_name("PIXELS");
  cmd->add_option("--image-format", args->image_format,
                  "the COCO exports' images: png (the dataset's, linked) or jpg (JPEG quality 95, images/<stem>.jpg, "
                  "as detectron2's COCO panoptic loader looks for them)")
      ->check(CLI::IsMember({"png", "jpg"}))
      ->default_val("png")
      ->type_name("FORMAT");
  cmd->add_option("--split", args->split,
                  "the Cityscapes split folder the frames go into (export a separate seed as val or test)")
      ->check(CLI::IsMember({"train", "val", "test"}))
      ->default_val("train")
      ->type_name("SPLIT");
  add_threads_option(*cmd, args->threads);
  add_output_flags(*cmd, args->output);
  cmd->footer("Examples:\n  silva export out/1234567890 --format coco-panoptic\n"
              "  silva export out/1234567890 --format all --out exports --overwrite\n"
              "  silva export out/1234567890 --format colmap --copy\n"
              "  silva export out/1234567890 --format coco-panoptic --image-format jpg   # for detectron2\n"
              "  silva export out/987 --format cityscapes --split val\n"
              "  silva export out/1234567890 --format rosbag2 && ros2 bag play out/1234567890/export/rosbag2/autopilot");
  return [args] { return export_command(*args); };
}

}  // namespace silva::app
