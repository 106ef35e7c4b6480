#include "render/video/ScreenRecorder.h"

#include "render/video/EncoderThread.h"
#include "render/video/Mp4Writer.h"

#include <algorithm>
#include <cmath>

namespace rv {

namespace {
// nearest-neighbour scaling: the view was resized while recording (rare; sharpness does not matter then)
Image scaled(const Image& in, int width, int height) {
  if (in.width == width && in.height == height) return in;
  Image out{width, height, std::vector<unsigned char>(static_cast<std::size_t>(width) * height * 3)};
  for (int y = 0; y < height; ++y) {
    const int sy = std::min(in.height - 1, static_cast<int>(static_cast<long>(y) * in.height / height));
    for (int x = 0; x < width; ++x) {
      const int sx = std::min(in.width - 1, static_cast<int>(static_cast<long>(x) * in.width / width));
      std::copy_n(&in.rgb[(static_cast<std::size_t>(sy) * in.width + sx) * 3], 3,
                  &out.rgb[(static_cast<std::size_t>(y) * width + x) * 3]);
    }
  }
  return out;
}
} // namespace

ScreenRecorder::ScreenRecorder(const std::string& path, int width, int height, int fps,
                               const EncoderSettings& encoder)
    : width_(std::max(2, width & ~1)), height_(std::max(2, height & ~1)), fps_(fps) {
  mp4_ = std::make_unique<Mp4Writer>(path, width_, height_, fps, encoder);
  // a second of frames queued: the GUI thread waits only when the encoder is that far behind
  encoder_ = std::make_unique<EncoderThread>(*mp4_, static_cast<std::size_t>(std::max(fps, 4)));
}

ScreenRecorder::~ScreenRecorder() {
  encoder_.reset(); // joins the worker before the unfinished writer removes its temporary file
}

void ScreenRecorder::writeUntil(long frame) {
  for (; written_ < frame; ++written_)
    encoder_->push(last_);
}

void ScreenRecorder::add(const Image& picture, double seconds) {
  if (picture.width <= 0 || picture.height <= 0) return;
  // frame k covers [k/fps, (k+1)/fps): those that begin before this picture show the previous one
  if (!last_.rgb.empty()) writeUntil(static_cast<long>(std::ceil(seconds * fps_ - 1e-9)));
  last_ = scaled(picture, width_, height_);
}

long ScreenRecorder::finish(double seconds) {
  if (last_.rgb.empty()) return 0;
  writeUntil(std::max(written_ + 1, std::lround(seconds * fps_)));
  encoder_->close();
  mp4_->finish();
  return written_;
}

} // namespace rv
