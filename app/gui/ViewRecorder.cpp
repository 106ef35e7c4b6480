// ViewRecorder.cpp -- the 3D view's pictures into a video: taken as painted, finished on a thread.
#include "app/gui/ViewRecorder.h"

#include "app/gui/QtVtkWidget.h"
#include "render/video/ScreenRecorder.h"

#include <QTimer>

namespace rv {

ViewRecorder::ViewRecorder(QtVtkWidget* view, QObject* parent) : QObject(parent), view_(view) {}

ViewRecorder::~ViewRecorder() {
  if (finisher_) finisher_->wait(); // a video being finished is written whole
  if (current_) {                   // a recording in progress is kept: its video is finished here
    view_->setFrameTap({});
    try {
      current_->video->finish(current_->clock.elapsed() / 1000.0);
    } catch (const std::exception&) { // nothing to tell any more; the writer leaves no half-written file
    }
  }
}

QString ViewRecorder::start(const QString& path, int fps, const EncoderSettings& encoder, QSize size,
                            QSize shown) {
  if (current_) return "a recording is in progress";
  auto r = std::make_unique<Recording>();
  try {
    r->video =
        std::make_shared<ScreenRecorder>(path.toStdString(), size.width(), size.height(), fps, encoder);
  } catch (const std::exception& e) {
    return QString::fromUtf8(e.what());
  }
  r->path = path;
  r->clock.start();
  current_ = std::move(r);
  view_->setFrameTap(
      [this](const Image& picture) {
        if (!current_ || !current_->error.isEmpty()) return;
        try {
          current_->video->add(picture, current_->clock.elapsed() / 1000.0);
        } catch (const std::exception& e) { // the disk is full, say: stop, and say why
          current_->error = QString::fromUtf8(e.what());
          QTimer::singleShot(0, this, &ViewRecorder::stop);
        }
      },
      size == shown ? QSize() : size);
  view_->update(); // the picture on screen now is the first frame
  return {};
}

void ViewRecorder::stop() {
  if (!current_) return;
  view_->setFrameTap({});
  const auto done = std::move(current_);
  const double seconds = done->clock.elapsed() / 1000.0;
  const QString path = done->path, error = done->error;
  // the encoder drains its queue on a thread of its own: the window stays responsive meanwhile
  QThread* finisher = QThread::create([this, video = done->video, seconds, path, error] {
    QString why = error;
    long frames = 0;
    if (why.isEmpty()) {
      try {
        frames = video->finish(seconds);
        if (frames == 0) why = "the view painted nothing";
      } catch (const std::exception& e) {
        why = QString::fromUtf8(e.what());
      }
    }
    QMetaObject::invokeMethod(this, [this, path, why, frames, seconds] {
      emit finished(why.isEmpty(), path, why, seconds, frames);
    });
  });
  connect(finisher, &QThread::finished, finisher, &QObject::deleteLater);
  finisher_ = finisher;
  finisher->start();
}

} // namespace rv
