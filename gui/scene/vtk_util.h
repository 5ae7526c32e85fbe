#pragma once
/// @file
/// Small VTK helpers shared by the scene's layers (private to gui/scene: only its .cpp files
/// include this): actors from sources, poses as user matrices, polylines, colours.

#include <vtkActor.h>
#include <vtkAlgorithmOutput.h>
#include <vtkPolyData.h>
#include <vtkPolyDataMapper.h>
#include <vtkSmartPointer.h>

#include <Eigen/Geometry>
#include <vector>

#include "core/chart_spec.h"

namespace saltus::gui::scene {

vtkSmartPointer<vtkPolyDataMapper> mapper_for(vtkAlgorithmOutput* port);
vtkSmartPointer<vtkPolyDataMapper> mapper_for(vtkPolyData* data);
vtkSmartPointer<vtkActor> actor_for(vtkPolyDataMapper* mapper);
void set_colour(vtkActor* actor, const Rgb& colour);
/// The actor's pose: world from its model coordinates.
void set_matrix(vtkActor* actor, const Eigen::Affine3d& world_from_model);
/// A line through the points, in order.
vtkSmartPointer<vtkPolyData> polyline(const std::vector<Eigen::Vector3d>& points);
/// `colour` `amount` of the way towards white.
Rgb lighter(const Rgb& colour, double amount);

}  // namespace saltus::gui::scene
