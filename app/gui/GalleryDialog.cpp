#include "app/gui/GalleryDialog.h"

#include "scenes/Gallery.h"

#include <QDialogButtonBox>
#include <QFileInfo>
#include <QLabel>
#include <QListWidget>
#include <QPushButton>
#include <QVBoxLayout>

namespace rv {

GalleryDialog::GalleryDialog(QWidget* parent, std::function<void(const QString&)> open)
    : QDialog(parent), list_(new QListWidget(this)), description_(new QLabel(this)), open_(std::move(open)) {
  setWindowTitle("Gallery: famous motions");
  list_->setObjectName("gallery_list");
  list_->setViewMode(QListView::IconMode);
  list_->setIconSize(QSize(240, 150));
  list_->setGridSize(QSize(260, 190));
  list_->setResizeMode(QListView::Adjust);
  list_->setMovement(QListView::Static);
  list_->setWordWrap(true);
  description_->setObjectName("gallery_description");
  description_->setWordWrap(true);
  description_->setMinimumHeight(60);
  try {
    for (const auto& g : galleryScenes()) {
      auto* item = new QListWidgetItem(QString::fromStdString(g.title), list_);
      const QString thumbnail = QString::fromStdString(galleryThumbnail(g));
      if (QFileInfo::exists(thumbnail)) item->setIcon(QIcon(thumbnail));
      item->setToolTip(QString::fromStdString(g.description));
      item->setData(Qt::UserRole, QString::fromStdString(g.path));
    }
  } catch (const std::exception& e) { // a broken gallery file: say which, show the rest of the dialog
    description_->setText(QString::fromStdString(e.what()));
  }
  connect(list_, &QListWidget::currentItemChanged, this, [this](QListWidgetItem* item) {
    if (item) description_->setText(item->toolTip());
  });
  connect(list_, &QListWidget::itemActivated, this, [this] { openSelected(); });
  auto* buttons = new QDialogButtonBox(QDialogButtonBox::Open | QDialogButtonBox::Close, this);
  connect(buttons->button(QDialogButtonBox::Open), &QPushButton::clicked, this, [this] { openSelected(); });
  connect(buttons, &QDialogButtonBox::rejected, this, &QDialog::reject);
  auto* layout = new QVBoxLayout(this);
  layout->addWidget(list_, 1);
  layout->addWidget(description_);
  layout->addWidget(buttons);
  resize(860, 720);
  if (list_->count() > 0) list_->setCurrentRow(0);
}

bool GalleryDialog::openSelected() {
  const QListWidgetItem* item = list_->currentItem();
  if (!item) return false;
  const QString path = item->data(Qt::UserRole).toString();
  accept();
  open_(path);
  return true;
}

} // namespace rv
