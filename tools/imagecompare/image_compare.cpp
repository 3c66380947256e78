#include "glass/image_compare.h"

#include <OpenImageIO/imagebuf.h>
#include <OpenImageIO/imagebufalgo.h>
#include <OpenImageIO/imageio.h>

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <memory>
#include <ostream>
#include <unistd.h>

namespace glass {
namespace {

// Reads an image file whole as 8-bit channels; returns false with a message when it cannot.
// ImageInput rather than ImageBuf(path): the latter goes through OpenImageIO's shared cache, which
// would hand back a file's old pixels after the file is rewritten within one process.
bool readImage(const std::string& path, OIIO::ImageBuf& image, std::string& error) {
  std::unique_ptr<OIIO::ImageInput> input = OIIO::ImageInput::open(path);
  if (!input) {
    error = "cannot read " + path + ": " + OIIO::geterror();
    return false;
  }
  OIIO::ImageSpec spec = input->spec();
  spec.set_format(OIIO::TypeDesc::UINT8);
  image.reset(spec);
  const bool read = input->read_image(0, 0, 0, spec.nchannels, OIIO::TypeDesc::UINT8,
                                      image.localpixels());
  if (!read) error = "cannot read " + path + ": " + input->geterror();
  input->close();
  return read;
}

// The pixels and channels both images have: the same size is required; channels are the first
// three (RGB), or fewer when an image has fewer.
bool commonRegion(const OIIO::ImageBuf& a, const OIIO::ImageBuf& b, const std::string& pathA,
                  const std::string& pathB, OIIO::ROI& roi, std::string& error) {
  const OIIO::ImageSpec& sa = a.spec();
  const OIIO::ImageSpec& sb = b.spec();
  if (sa.width != sb.width || sa.height != sb.height) {
    error = "sizes differ: " + pathA + " is " + std::to_string(sa.width) + "x" +
            std::to_string(sa.height) + ", " + pathB + " is " + std::to_string(sb.width) + "x" +
            std::to_string(sb.height);
    return false;
  }
  roi = a.roi();
  roi.chbegin = 0;
  roi.chend = std::min({sa.nchannels, sb.nchannels, 3});
  return true;
}

bool parseNumber(const std::string& text, double& value) {
  if (text.empty()) return false;
  char* end = nullptr;
  errno = 0;
  value = std::strtod(text.c_str(), &end);
  return errno == 0 && end == text.c_str() + text.size() && !std::isnan(value);
}

}  // namespace

std::optional<ImageDifference> compareImageFiles(const std::string& pathA, const std::string& pathB,
                                                 std::string& error) {
  OIIO::ImageBuf a, b;
  OIIO::ROI roi;
  if (!readImage(pathA, a, error) || !readImage(pathB, b, error) ||
      !commonRegion(a, b, pathA, pathB, roi, error))
    return std::nullopt;

  // One thread: the sums then add up in the same order every run.
  const OIIO::ImageBufAlgo::CompareResults result = OIIO::ImageBufAlgo::compare(
      a, b, float(kPixelOffThreshold), float(kPixelOffThreshold), roi, /*nthreads=*/1);
  // compare() also raises `error` when some pixel is beyond the threshold; only an error with no
  // such pixel means the comparison itself failed.
  if (result.error && result.nfail == 0) {
    error = "cannot compare " + pathA + " with " + pathB + ": " + OIIO::geterror();
    return std::nullopt;
  }

  ImageDifference d;
  d.width = roi.width();
  d.height = roi.height();
  d.channels = roi.nchannels();
  d.meanError = result.meanerror;
  d.maxError = result.maxerror;
  d.maxErrorX = result.maxx;
  d.maxErrorY = result.maxy;
  // PSNR for a peak value of 1: 20 log10(1 / RMS); identical images have no finite PSNR.
  d.psnr = result.rms_error > 0.0 ? 20.0 * std::log10(1.0 / result.rms_error)
                                  : std::numeric_limits<double>::infinity();
  d.pixelsOff = static_cast<long long>(result.nfail);
  const double pixels = double(d.width) * double(d.height);
  d.percentOff = pixels > 0.0 ? 100.0 * double(d.pixelsOff) / pixels : 0.0;
  return d;
}

bool exceedsLimits(const ImageDifference& difference, const ImageCompareLimits& limits,
                   std::vector<std::string>* reasons) {
  bool exceeded = false;
  char line[160];
  if (limits.failPsnr && difference.psnr < *limits.failPsnr) {
    exceeded = true;
    if (std::isinf(*limits.failPsnr))
      std::snprintf(line, sizeof line, "images differ (PSNR %.2f dB), identical images required",
                    difference.psnr);
    else
      std::snprintf(line, sizeof line, "PSNR %.2f dB is below %.2f dB", difference.psnr,
                    *limits.failPsnr);
    if (reasons) reasons->push_back(line);
  }
  if (limits.failPercent && difference.percentOff > *limits.failPercent) {
    exceeded = true;
    std::snprintf(line, sizeof line, "%.4f%% of pixels off by more than 8/255, limit %.4f%%",
                  difference.percentOff, *limits.failPercent);
    if (reasons) reasons->push_back(line);
  }
  return exceeded;
}

bool writeDiffImage(const std::string& pathA, const std::string& pathB, const std::string& diffPath,
                    std::string& error) {
  OIIO::ImageBuf a, b;
  OIIO::ROI roi;
  if (!readImage(pathA, a, error) || !readImage(pathB, b, error) ||
      !commonRegion(a, b, pathA, pathB, roi, error))
    return false;

  const int w = roi.width(), h = roi.height(), channels = roi.nchannels();
  std::vector<unsigned char> pixelsA(size_t(w) * h * channels), pixelsB(pixelsA.size());
  if (!a.get_pixels(roi, OIIO::TypeDesc::UINT8, pixelsA.data()) ||
      !b.get_pixels(roi, OIIO::TypeDesc::UINT8, pixelsB.data())) {
    error = "cannot read pixels of " + pathA + " or " + pathB;
    return false;
  }

  OIIO::ImageBuf diff(OIIO::ImageSpec(w, h, 3, OIIO::TypeDesc::UINT8));
  std::vector<unsigned char> out(size_t(w) * h * 3);
  const int offSteps = int(kPixelOffThreshold * 255.0);  // 8: off means a difference above this
  for (size_t p = 0; p < size_t(w) * h; ++p) {
    int largest = 0, sum = 0;
    for (int c = 0; c < channels; ++c) {
      largest = std::max(largest, std::abs(int(pixelsA[p * channels + c]) -
                                           int(pixelsB[p * channels + c])));
      sum += pixelsA[p * channels + c];
    }
    unsigned char* rgb = &out[p * 3];
    if (largest > offSteps) {
      rgb[0] = 255, rgb[1] = 0, rgb[2] = 0;
    } else if (largest > 0) {
      rgb[0] = 255, rgb[1] = 220, rgb[2] = 0;
    } else {
      const unsigned char grey = static_cast<unsigned char>(sum / channels / 4);
      rgb[0] = rgb[1] = rgb[2] = grey;
    }
  }
  diff.set_pixels(diff.roi(), OIIO::TypeDesc::UINT8, out.data());

  // Write beside the target and rename, so that a reader never sees half a file.
  const std::string tempPath = diffPath + ".tmp" + std::to_string(getpid()) + ".png";
  if (!diff.write(tempPath, OIIO::TypeDesc::UINT8, "png") ||
      std::rename(tempPath.c_str(), diffPath.c_str()) != 0) {
    std::remove(tempPath.c_str());
    error = "cannot write " + diffPath + (diff.has_error() ? ": " + diff.geterror() : "");
    return false;
  }
  return true;
}

void printImageDifference(std::ostream& out, const ImageDifference& d) {
  char line[200];
  std::snprintf(line, sizeof line, "size:       %d x %d, %d channels compared\n", d.width,
                d.height, d.channels);
  out << line;
  if (std::isinf(d.psnr))
    out << "PSNR:       inf dB (identical)\n";
  else {
    std::snprintf(line, sizeof line, "PSNR:       %.2f dB\n", d.psnr);
    out << line;
  }
  std::snprintf(line, sizeof line, "mean error: %.6f (%.3f/255)\n", d.meanError,
                d.meanError * 255.0);
  out << line;
  std::snprintf(line, sizeof line,
                "max error:  %.6f (%.0f/255) at pixel (%d, %d), row 0 at the top\n", d.maxError,
                d.maxError * 255.0, d.maxErrorX, d.maxErrorY);
  out << line;
  std::snprintf(line, sizeof line, "pixels off: %lld of %lld (%.4f%%) by more than 8/255\n",
                d.pixelsOff, (long long)d.width * d.height, d.percentOff);
  out << line;
}

std::optional<ImageCompareRequest> parseImageCompareArguments(const std::vector<std::string>& args,
                                                              std::string& error) {
  ImageCompareRequest request;
  std::vector<std::string> paths;
  for (size_t i = 0; i < args.size(); ++i) {
    const std::string& arg = args[i];
    const bool takesValue = arg == "--fail-psnr" || arg == "--fail-percent" || arg == "--diff";
    if (takesValue && i + 1 == args.size()) {
      error = arg + " needs a value";
      return std::nullopt;
    }
    if (arg == "--fail-psnr" || arg == "--fail-percent") {
      double value = 0.0;
      if (!parseNumber(args[++i], value) || value < 0.0) {
        error = arg + " needs a number >= 0 (or inf), not '" + args[i] + "'";
        return std::nullopt;
      }
      (arg == "--fail-psnr" ? request.limits.failPsnr : request.limits.failPercent) = value;
    } else if (arg == "--diff") {
      request.diffPath = args[++i];
    } else if (arg.size() > 1 && arg[0] == '-') {
      error = "unknown option " + arg;
      return std::nullopt;
    } else {
      paths.push_back(arg);
    }
  }
  if (paths.size() != 2) {
    error = "expected two images, A.png B.png; got " + std::to_string(paths.size());
    return std::nullopt;
  }
  request.pathA = paths[0];
  request.pathB = paths[1];
  return request;
}

int runImageCompare(const ImageCompareRequest& request, std::ostream& out, std::ostream& err) {
  std::string error;
  const std::optional<ImageDifference> difference =
      compareImageFiles(request.pathA, request.pathB, error);
  if (!difference) {
    err << "compare: " << error << "\n";
    return 2;
  }
  printImageDifference(out, *difference);

  std::vector<std::string> reasons;
  const bool failed = exceedsLimits(*difference, request.limits, &reasons);
  for (const std::string& reason : reasons) out << "FAIL: " << reason << "\n";

  if (!request.diffPath.empty() && (failed || !request.diffOnlyOnFailure)) {
    if (!writeDiffImage(request.pathA, request.pathB, request.diffPath, error)) {
      err << "compare: " << error << "\n";
      return 2;
    }
    out << "diff image: " << request.diffPath
        << " (red: off by more than 8/255, yellow: smaller differences)\n";
  }
  return failed ? 1 : 0;
}

}  // namespace glass
