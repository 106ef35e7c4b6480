// GalleryDialog.h -- File > Gallery: the curated scenes of scenes/gallery (scenes/Gallery.h) as thumbnails
// with their titles; the selected one's description says what to watch, and Open (or a double click) opens
// it in the main window.
#pragma once
#include <QDialog>
#include <functional>

class QListWidget;
class QLabel;

namespace rv {

class GalleryDialog : public QDialog {
public:
  /// `open` opens a scene file (the main window's openScene); it is called with the chosen scene's path.
  GalleryDialog(QWidget* parent, std::function<void(const QString&)> open);
  /// The list of scenes (tests).
  QListWidget* list() const { return list_; }
  /// Opens the selected scene and closes the dialog; false when none is selected.
  bool openSelected();

private:
  QListWidget* list_;
  QLabel* description_;
  std::function<void(const QString&)> open_;
};

} // namespace rv
