#include "scene/vtk_util.h"

#include <vtkCellArray.h>
#include <vtkMatrix4x4.h>
#include <vtkNew.h>
#include <vtkPoints.h>
#include <vtkPolyLine.h>
#include <vtkProperty.h>

namespace saltus::gui::scene {

vtkSmartPointer<vtkPolyDataMapper> mapper_for(vtkAlgorithmOutput* port) {
  auto mapper = vtkSmartPointer<vtkPolyDataMapper>::New();
  mapper->SetInputConnection(port);
  return mapper;
}

vtkSmartPointer<vtkPolyDataMapper> mapper_for(vtkPolyData* data) {
  auto mapper = vtkSmartPointer<vtkPolyDataMapper>::New();
  mapper->SetInputData(data);
  return mapper;
}

vtkSmartPointer<vtkActor> actor_for(vtkPolyDataMapper* mapper) {
  auto actor = vtkSmartPointer<vtkActor>::New();
  actor->SetMapper(mapper);
  return actor;
}

void set_colour(vtkActor* actor, const Rgb& c) {
  actor->GetProperty()->SetColor(c.r, c.g, c.b);
}

void set_matrix(vtkActor* actor, const Eigen::Affine3d& world_from_model) {
  vtkNew<vtkMatrix4x4> m;
  for (int r = 0; r < 4; ++r)
    for (int c = 0; c < 4; ++c)
      m->SetElement(r, c, world_from_model.matrix()(r, c));
  actor->SetUserMatrix(m);
}

vtkSmartPointer<vtkPolyData> polyline(const std::vector<Eigen::Vector3d>& points) {
  vtkNew<vtkPoints> pts;
  vtkNew<vtkPolyLine> line;
  line->GetPointIds()->SetNumberOfIds(static_cast<vtkIdType>(points.size()));
  for (std::size_t i = 0; i < points.size(); ++i) {
    pts->InsertNextPoint(points[i].x(), points[i].y(), points[i].z());
    line->GetPointIds()->SetId(static_cast<vtkIdType>(i), static_cast<vtkIdType>(i));
  }
  vtkNew<vtkCellArray> cells;
  cells->InsertNextCell(line);
  auto data = vtkSmartPointer<vtkPolyData>::New();
  data->SetPoints(pts);
  data->SetLines(cells);
  return data;
}

Rgb lighter(const Rgb& c, double amount) {
  return {c.r + amount * (1.0 - c.r), c.g + amount * (1.0 - c.g), c.b + amount * (1.0 - c.b)};
}

}  // namespace saltus::gui::scene
