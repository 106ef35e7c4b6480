#include "render/video/VideoExport.h"

#include "render/Snapshot.h"
#include "render/video/Mp4Writer.h"

#include <cmath>
#include <vtkRenderWindow.h>

namespace rv {

void playTo(VisualScene& scene, Integrator& integrator, double t, Eigen::VectorXd& work) {
  const int dir = integrator.direction();
  while (dir * (integrator.time() - t) < 0) {
    integrator.step();
    if (dir * (integrator.time() - t) < 0) scene.advance(integrator.time(), integrator.state());
  }
  if (integrator.time() == t)
    work = integrator.state();
  else
    integrator.interpolate(t, work);
  scene.show(t, work);
}

long exportVideo(VisualScene& scene, vtkRenderWindow* window, Integrator& integrator, const VideoSpec& spec,
                 const std::function<bool(long, long)>& progress) {
  Mp4Writer mp4(spec.path, spec.width, spec.height, spec.fps, spec.encoder);
  const long total = std::lround(spec.duration * spec.fps);
  const double t0 = integrator.time();
  window->SetSize(spec.width, spec.height);
  Eigen::VectorXd x(integrator.state().size());
  long k = 0;
  for (; k < total; ++k) {
    if (progress && !progress(k, total)) break;
    playTo(scene, integrator, t0 + integrator.direction() * spec.speed * static_cast<double>(k) / spec.fps,
           x);
    const Image frame = capture(window);
    mp4.add(frame.rgb.data());
  }
  mp4.finish();
  return k;
}

} // namespace rv
