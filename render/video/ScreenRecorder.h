// ScreenRecorder.h -- the pictures of a live view into an MP4 whose length follows the wall clock: each
// picture stays on screen until the next one arrives (a paused view is a still picture for as long as it was
// paused), so the video lasts as long as the recording did and shows what the user saw, camera moves
// included.
// (`rollviz video` is the other way: frames at exact simulation times, rendered offline.)
#pragma once
#include "render/Snapshot.h"
#include "render/video/Mp4Writer.h"

#include <memory>
#include <string>

namespace rv {

class EncoderThread;
class Mp4Writer;

class ScreenRecorder {
public:
  /// Width and height are made even (the encoder's yuv420p). Throws InputError for a bad path,
  /// ComputationError when the encoder cannot be opened (Mp4Writer's).
  ScreenRecorder(const std::string& path, int width, int height, int fps,
                 const EncoderSettings& encoder = {});
  ~ScreenRecorder();
  /// The view's picture at `seconds` since the recording began (non-decreasing); every video frame that
  /// begins before it shows the picture before. A picture of another size is scaled to the video's.
  void add(const Image& picture, double seconds);
  /// Ends the video at `seconds`: the last picture holds until then, and the file appears. Returns the
  /// number of frames (0 and no file when no picture ever came).
  long finish(double seconds);
  long frames() const { return written_; }
  int width() const { return width_; }
  int height() const { return height_; }

private:
  void writeUntil(long frame);
  int width_, height_, fps_;
  long written_ = 0;
  Image last_; ///< the picture on screen now, at the video's size
  std::unique_ptr<Mp4Writer> mp4_;
  std::unique_ptr<EncoderThread> encoder_;
};

} // namespace rv
