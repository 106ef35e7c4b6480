// ViewRecorder.h -- Record… of the 3D view: the pictures the view paints (QtVtkWidget's frame tap), each
// with its wall-clock time, encoded into an MP4 by a ScreenRecorder on its own thread -- the run as it plays,
// camera moves and pauses included. Stop hands the encoder's queue to a finishing thread, so the window stays
// responsive while the file is written; finished() says how it went. A recording still going when the
// recorder is destroyed is finished there (the file is written whole, never half).
#pragma once
#include "render/video/VideoExport.h"

#include <QElapsedTimer>
#include <QObject>
#include <QPointer>
#include <QSize>
#include <QString>
#include <QThread>
#include <memory>

namespace rv {

class QtVtkWidget;
class ScreenRecorder;

class ViewRecorder : public QObject {
  Q_OBJECT
public:
  ViewRecorder(QtVtkWidget* view, QObject* parent);
  ~ViewRecorder() override;
  /// Starts recording into `path` at `fps` frames a second, each frame `size` (the view's picture when it
  /// equals `shown`, else rendered again offscreen at that size). Returns "" or why it cannot.
  QString start(const QString& path, int fps, const EncoderSettings& encoder, QSize size, QSize shown);
  /// Ends the recording (nothing when none); finished() follows once the file is written.
  void stop();
  bool recording() const { return current_ != nullptr; }

signals:
  /// The file of a stopped recording is written (`ok`), or why not; `seconds` recorded, `frames` encoded.
  void finished(bool ok, const QString& path, const QString& why, double seconds, long frames);

private:
  struct Recording {
    std::shared_ptr<ScreenRecorder> video;
    QElapsedTimer clock;
    QString path;
    QString error; ///< the first encoder failure while recording
  };
  QtVtkWidget* view_;
  std::unique_ptr<Recording> current_;
  QPointer<QThread> finisher_; ///< finishing the last recording's file
};

} // namespace rv
