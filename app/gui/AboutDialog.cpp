#include "app/gui/AboutDialog.h"

#include "app/cli/BuildInfo.h"
#include "app/gui/QtVtkWidget.h"

#include <QCoreApplication>
#include <QDialogButtonBox>
#include <QFileInfo>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QLabel>
#include <QOpenGLContext>
#include <QOpenGLFunctions>
#include <QProcess>
#include <QVBoxLayout>

namespace rv {

namespace {
QString row(const std::string& name, const std::string& value) {
  return QString("<tr><td>%1&nbsp;&nbsp;</td><td>%2</td></tr>")
      .arg(QString::fromStdString(name).toHtmlEscaped(), QString::fromStdString(value).toHtmlEscaped());
}
QString table(const std::vector<Fact>& facts) {
  QString html = "<table>";
  for (const auto& f : facts)
    html += row(f.name, f.value);
  return html + "</table>";
}
QString warning(const RendererInfo& info) {
  const auto w = softwareRendererWarning(info);
  return w.empty() ? QString()
                   : "<p style='color:#a05000'>" + QString::fromStdString(w).toHtmlEscaped() + "</p>";
}
// the rollviz executable to ask: this one, or the one the environment names (tests run from their own
// binaries)
QString rollvizExecutable() {
  if (QString env = qEnvironmentVariable("ROLLVIZ_EXE"); !env.isEmpty()) return env;
  const QString self = QCoreApplication::applicationFilePath();
  return QFileInfo(self).fileName() == "rollviz" ? self : QString();
}
} // namespace

AboutDialog::AboutDialog(QtVtkWidget* view, QWidget* parent) : QDialog(parent) {
  setObjectName("about");
  setWindowTitle("About rollviz");
  setAttribute(Qt::WA_DeleteOnClose);
  auto facts = buildFacts();
  facts.push_back({"Qt", qVersion()});
  head_ = "<h3>rollviz</h3><p>Bodies rolling without slipping, and the tools of nonlinear dynamics.</p>" +
          table(facts);

  // the on-screen view: its own GLX context (the GUI never makes an EGL context: the GLX shim would follow
  // it)
  RendererInfo screen;
  screen.backend = "glx";
  if (view->context()) {
    view->makeCurrent();
    auto* gl = view->context()->functions();
    auto text = [&](GLenum what) {
      const GLubyte* s = gl->glGetString(what);
      return s ? std::string(reinterpret_cast<const char*>(s)) : std::string("?");
    };
    screen.vendor = text(GL_VENDOR);
    screen.renderer = text(GL_RENDERER);
    screen.version = text(GL_VERSION);
    screen.software = isSoftwareRenderer(screen.renderer);
    view->doneCurrent();
  }
  head_ +=
      "<p><b>This window's 3D view</b> (Qt's OpenGL context)</p>" +
      table(
          {{"GL_VENDOR", screen.vendor}, {"GL_RENDERER", screen.renderer}, {"GL_VERSION", screen.version}}) +
      warning(screen);

  text_ = new QLabel(this);
  text_->setTextInteractionFlags(Qt::TextSelectableByMouse);
  text_->setWordWrap(true);
  text_->setMinimumWidth(560);
  auto* buttons = new QDialogButtonBox(QDialogButtonBox::Close, this);
  connect(buttons, &QDialogButtonBox::rejected, this, &QDialog::close);
  auto* layout = new QVBoxLayout(this);
  layout->addWidget(text_);
  layout->addWidget(buttons);

  const QString exe = rollvizExecutable();
  if (exe.isEmpty()) {
    showHeadless("<p>Run <tt>rollviz info</tt> for the renderer of headless pictures.</p>");
    return;
  }
  showHeadless("<p><i>asking <tt>rollviz info</tt> …</i></p>");
  info_ = new QProcess(this); // a process of its own: an EGL context here would confuse the GLX shim
  connect(info_, &QProcess::finished, this, [this](int code, QProcess::ExitStatus status) {
    const auto json = QJsonDocument::fromJson(info_->readAllStandardOutput()).object()["renderer"].toObject();
    if (status != QProcess::NormalExit || code != 0 || json.isEmpty()) {
      showHeadless("<p>The headless renderer could not be made: " +
                   QString::fromLocal8Bit(info_->readAllStandardError()).trimmed().toHtmlEscaped() + "</p>");
      return;
    }
    RendererInfo r;
    r.backend = json["backend"].toString().toStdString();
    r.context = json["context"].toString().toStdString();
    for (const auto& d : json["devices"].toArray())
      r.devices.push_back(d.toString().toStdString());
    r.vendor = json["vendor"].toString().toStdString();
    r.renderer = json["renderer"].toString().toStdString();
    r.version = json["version"].toString().toStdString();
    r.software = json["software"].toBool();
    showHeadless(table(rendererFacts(r)) + warning(r));
  });
  info_->start(exe, {"info", "--json"});
}

void AboutDialog::showHeadless(const QString& html) {
  text_->setText(
      head_ + "<p><b>Headless pictures</b> (rollviz render, video, chart; <tt>rollviz info</tt>)</p>" + html);
  adjustSize();
  if (!info_ || info_->state() == QProcess::NotRunning) emit headlessKnown();
}

} // namespace rv
