// Actors.h -- the one way visual objects turn a VTK source into an actor (source -> mapper -> actor).
#pragma once
#include <vtkActor.h>
#include <vtkAlgorithm.h>
#include <vtkPolyDataMapper.h>
#include <vtkSmartPointer.h>
#include <vtkSphereSource.h>

namespace rv {

/// An actor drawing the output of `source`.
inline vtkSmartPointer<vtkActor> actorOf(vtkAlgorithm* source) {
  vtkNew<vtkPolyDataMapper> mapper;
  mapper->SetInputConnection(source->GetOutputPort());
  auto actor = vtkSmartPointer<vtkActor>::New();
  actor->SetMapper(mapper);
  return actor;
}

/// A sphere of this radius at the origin (markers, the apexes' dots, the unit sphere).
inline vtkSmartPointer<vtkActor> sphereActor(double radius, int thetaResolution, int phiResolution) {
  vtkNew<vtkSphereSource> s;
  s->SetRadius(radius);
  s->SetThetaResolution(thetaResolution);
  s->SetPhiResolution(phiResolution);
  return actorOf(s);
}

} // namespace rv
