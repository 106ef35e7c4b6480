// Mp4Writer.h -- RGB frames into an MP4 file through libav: H.264 (libx264) when available, MPEG-4 part 2
// otherwise. Written to a temporary name; finish() makes the file appear, destruction without finish()
// leaves nothing behind.
#pragma once
#include <memory>
#include <string>

namespace rv {

/// The encoder and its settings (the scene's "video" section: crf, preset).
struct EncoderSettings {
  std::string codec = "libx264";   ///< a libav encoder; MPEG-4 part 2 when it is not there
  std::string preset = "veryfast"; ///< x264's speed against size
  int crf = 20;                    ///< x264's constant rate factor, 0 (lossless) .. 51
};

class Mp4Writer {
public:
  /// Width and height must be even (yuv420p). Throws InputError for a bad size or path, ComputationError
  /// when the encoder cannot be opened.
  Mp4Writer(const std::string& path, int width, int height, int fps, const EncoderSettings& encoder = {},
            const std::string& what = "-o");
  ~Mp4Writer();
  /// Appends one frame: width * height * 3 bytes of RGB, rows from the top.
  void add(const unsigned char* rgbTopDown);
  /// Drains the encoder, writes the trailer and renames the file into place.
  void finish();
  const char* codecName() const;
  long frames() const;

private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

/// The libav libraries this executable runs with, e.g. "libavcodec 59.37.100, libavformat 59.27.100, ...".
std::string libavVersions();

} // namespace rv
