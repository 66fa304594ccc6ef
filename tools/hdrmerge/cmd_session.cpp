#include "commands.hpp"

#include <cstdio>
#include <filesystem>

#include <opencv2/imgproc.hpp>

#include "capture/rig.hpp"
#include "capture/silhouette.hpp"
#include "core/error.hpp"
#include "core/quote.hpp"
#include "core/file_io.hpp"
#include "core/input_name.hpp"
#include "core/parallel_for.hpp"
#include "core/progress.hpp"
#include "core/sha256.hpp"
#include "core/threads.hpp"
#include "formats/image/exr_extras.hpp"
#include "formats/image/image_io.hpp"
#include "formats/input.hpp"
#include "formats/table/table_io.hpp"
#include "hdr/merge.hpp"
#include "response_recovery.hpp"
#include "session_manifest.hpp"
#include "stack_files.hpp"

namespace fest::hdrmerge_tool {

namespace fs = std::filesystem;
using nlohmann::json;

namespace {

// A shot's picture, checked against its recorded hash, as 8-bit codes for the response
// (16-bit values keep their top byte: round(Z / 257)).
// A shot's pixels as stored (8 or 16-bit), its SHA-256 checked.
cv::Mat read_stored_shot(const std::string& session, const SessionShot& s) {
  const std::string path = (fs::path(session) / s.file).string();
  const std::string bytes = read_input(path);
  if (sha256_hex(bytes) != s.sha256) throw bad_input("file differs from the manifest's sha256 ({})", path);
  Image image;
  try {
    image = formats::read_image(bytes, formats::detect_format(bytes, path));
  } catch (const Error& e) {
    throw Error(e.status(), with_location(e.what(), path));
  }
  if (image.pixels.depth() != CV_8U && image.pixels.depth() != CV_16U)
    throw bad_input("expected an 8 or 16-bit shot ({})", path);
  return image.pixels;
}

// 8-bit pixels for the merge: 16-bit shots scaled by 1/257.
cv::Mat to_8bit(const cv::Mat& m) {
  if (m.depth() == CV_8U) return m;
  cv::Mat out;
  m.convertTo(out, CV_8U, 1.0 / 257.0);
  return out;
}

cv::Mat read_shot(const std::string& session, const SessionShot& s) { return to_8bit(read_stored_shot(session, s)); }

// The takes of one exposure averaged at the stored depth, before the 8-bit conversion:
// N takes lower the noise by sqrt(N) (the mean of noisy samples, rounded once).
cv::Mat read_takes(const std::string& session, const std::vector<SessionShot>& takes) {
  if (takes.size() == 1) return read_shot(session, takes.front());
  cv::Mat first = read_stored_shot(session, takes.front());
  cv::Mat sum;
  first.convertTo(sum, CV_64F);
  for (std::size_t i = 1; i < takes.size(); ++i) {
    const cv::Mat m = read_stored_shot(session, takes[i]);
    if (m.size() != first.size() || m.type() != first.type())
      throw bad_input("takes of one exposure differ in size or type ({} and {})", takes.front().file, takes[i].file);
    cv::accumulate(m, sum);
  }
  cv::Mat mean;
  sum.convertTo(mean, first.depth(), 1.0 / double(takes.size()));
  return to_8bit(mean);
}

std::string relative_to(const std::string& path, const std::string& session) {
  std::error_code ec;
  const fs::path p = fs::weakly_canonical(fs::absolute(path), ec);
  const fs::path base = fs::weakly_canonical(fs::absolute(session), ec);
  const fs::path rel = p.lexically_relative(base);
  if (rel.empty() || *rel.begin() == "..") return p.string();
  return rel.string();
}

}  // namespace

int run_session(const SessionOptions& a) {
  const std::string where = input_name(a.manifest);
  const json manifest = formats::parse(formats::load_input(a.manifest), formats::read_json_document);
  const SessionManifest parsed = parse_session_manifest(manifest, where);
  std::string session = is_stdio(a.manifest) ? parsed.session : fs::path(a.manifest).parent_path().string();
  if (session.empty()) session = ".";
  const std::string out_dir = a.output_dir.empty() ? (fs::path(session) / "hdr").string() : a.output_dir;
  const std::vector<ExposureSet>& sets = parsed.sets;
  const std::map<int, SessionShot>& silhouettes = parsed.silhouettes;

  auto stack_of = [&](const ExposureSet& s) {
    hdr::ExposureStack stack;
    for (const std::vector<SessionShot>& takes : s.exposures) {
      stack.images.push_back(read_takes(session, takes));
      stack.times.push_back(takes.front().exposure_s);
    }
    hdr::validate_stack(stack);
    return stack;
  };

  // One camera, one response: recovered from the first set unless given.
  hdr::Response response;
  if (!a.response_in.empty()) {
    response = response_from_table(formats::parse(formats::load_input(a.response_in), formats::read_table));
  } else {
    response = recover_response(stack_of(sets.front()), a.method, a.samples, a.lambda);
  }
  const std::string response_csv = formats::write_table(response_table(response), formats::Format::csv);
  const std::string response_sha = sha256_hex(response_csv);

  std::error_code ec;
  fs::create_directories(out_dir, ec);
  if (ec) throw io_error("cannot create {}: {}", out_dir, ec.message());

  // Sets (and masks) on worker threads, one set at a time each; the first error wins.
  std::vector<capture::RigImage> rig(sets.size());
  std::vector<int> mask_angles;
  for (const auto& [angle, shot] : silhouettes) mask_angles.push_back(angle);
  const std::size_t jobs = sets.size() + mask_angles.size();
  Progress bar("hdrmerge session", jobs, progress_wanted(a.progress));
  ProgressCounter done(bar.callback(), jobs);
  parallel_for(jobs, resolve_threads(a.threads), [&](std::size_t j) {
    if (j < sets.size()) {
      const ExposureSet& s = sets[j];
      const hdr::MergeResult merged = hdr::merge_debevec(stack_of(s), response, 1);
      cv::Mat rgb = merged.radiance;
      if (rgb.channels() == 1) cv::cvtColor(rgb, rgb, cv::COLOR_GRAY2RGB);
      formats::ExrExtras extras;
      extras.channels = {{"valid", merged.valid}};
      std::vector<float> exposures;
      for (const std::vector<SessionShot>& takes : s.exposures) exposures.push_back(float(takes.front().exposure_s));
      extras.float_vectors["exposures"] = exposures;
      extras.strings["responseSha256"] = response_sha;
      extras.strings["lightId"] = s.light;
      extras.doubles["turntableAngleDeg"] = s.angle_deg;
      const std::string name = fmt::format("a{:03}_{}.exr", s.angle_index, s.light);
      const std::string path = (fs::path(out_dir) / name).string();
      write_output(path, formats::write_exr_with_extras(rgb, extras, !a.full_float));
      rig[j] = {relative_to(path, session), "", s.angle_index, s.angle_deg, s.light};
    } else {
      const int angle = mask_angles[j - sets.size()];
      const std::string path = (fs::path(out_dir) / fmt::format("a{:03}_mask.png", angle)).string();
      const cv::Mat shot = read_shot(session, silhouettes.at(angle));
      cv::Mat mask;
      try {
        mask = capture::silhouette_mask(shot);
      } catch (const Error& e) {
        throw Error(e.status(), with_location(e.what(), silhouettes.at(angle).file));
      }
      write_output(path, formats::write_image(Image{mask, ColorSpace::srgb}, formats::Format::png));
    }
    done.step();
  });
  bar.finish();

  for (capture::RigImage& r : rig)
    if (silhouettes.count(r.angle_index))
      r.mask = relative_to((fs::path(out_dir) / fmt::format("a{:03}_mask.png", r.angle_index)).string(), session);
  const json doc = capture::build_rig(manifest, rig, session, where);
  std::fputs(formats::write_json(doc).c_str(), stdout);
  return 0;
}

}  // namespace fest::hdrmerge_tool
