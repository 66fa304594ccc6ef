#include "marching_cubes.hpp"

#include <cmath>
#include <vector>

#include <vtkCellArray.h>
#include <vtkDoubleArray.h>
#include <vtkFlyingEdges3D.h>
#include <vtkImageData.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkPolyData.h>

#include "core/error.hpp"
#include "softobj/shrinkwrap.hpp"

namespace fest::softobj_tool {

TriMesh marching_cubes(const softobj::Field& field, double iso, double rho, double h, std::size_t max_vertices) {
  const auto& c = field.skeleton();
  Eigen::Vector3d lo = Eigen::Vector3d::Constant(1e300), hi = -lo;
  for (const auto& t : c.terms)
    for (const auto& v : t.v) lo = lo.cwiseMin(v), hi = hi.cwiseMax(v);
  const double grow = rho + 2 * h;
  lo.array() -= grow;
  hi.array() += grow;
  int n[3];
  double cells = 1;
  for (int k = 0; k < 3; ++k) n[k] = static_cast<int>(std::ceil((hi[k] - lo[k]) / h)) + 1, cells *= n[k];
  if (cells > 4e8) throw runtime_failure("a grid of {} x {} x {} samples is too large", n[0], n[1], n[2]);
  vtkNew<vtkImageData> img;
  img->SetDimensions(n[0], n[1], n[2]);
  img->SetOrigin(lo.x(), lo.y(), lo.z());
  img->SetSpacing(h, h, h);
  vtkNew<vtkDoubleArray> values;
  values->SetName("f");
  values->SetNumberOfTuples(static_cast<vtkIdType>(cells));
  vtkIdType id = 0;
  for (int z = 0; z < n[2]; ++z)
    for (int y = 0; y < n[1]; ++y)
      for (int x = 0; x < n[0]; ++x) values->SetValue(id++, field.value(lo + h * Eigen::Vector3d(x, y, z)));
  img->GetPointData()->SetScalars(values);
  vtkNew<vtkFlyingEdges3D> fe;
  fe->SetInputData(img);
  fe->SetValue(0, iso);
  fe->ComputeNormalsOff();
  fe->ComputeGradientsOff();
  fe->ComputeScalarsOff();
  fe->Update();
  vtkPolyData* out = fe->GetOutput();
  if (static_cast<std::size_t>(out->GetNumberOfPoints()) > max_vertices)
    throw runtime_failure("more than {} vertices (the vertex limit)", max_vertices);
  TriMesh m;
  m.request_vertex_normals();
  std::vector<TriMesh::VertexHandle> vh;
  for (vtkIdType i = 0; i < out->GetNumberOfPoints(); ++i) {
    double p[3];
    out->GetPoint(i, p);
    Eigen::Vector3d r(p[0], p[1], p[2]);
    softobj::project_to_iso(field, r, iso, 1e-12, h);
    vh.push_back(m.add_vertex(TriMesh::Point(r.x(), r.y(), r.z())));
    const Eigen::Vector3d g = -field.eval(r).grad.normalized();
    m.set_normal(vh.back(), TriMesh::Normal(g.x(), g.y(), g.z()));
  }
  vtkCellArray* polys = out->GetPolys();
  vtkIdType npts;
  const vtkIdType* pts;
  std::vector<std::array<vtkIdType, 3>> tris;
  for (polys->InitTraversal(); polys->GetNextCell(npts, pts);)
    if (npts == 3) tris.push_back({pts[0], pts[1], pts[2]});
  // Orient outward: the field decreases outwards, so a face normal should oppose grad f.
  double s = 0;
  for (const auto& t : tris) {
    const auto a = m.point(vh[t[0]]), b = m.point(vh[t[1]]), cc = m.point(vh[t[2]]);
    s += ((b - a) % (cc - a)) | m.normal(vh[t[0]]);
  }
  for (const auto& t : tris)
    if (s >= 0) m.add_face(vh[t[0]], vh[t[1]], vh[t[2]]); else m.add_face(vh[t[0]], vh[t[2]], vh[t[1]]);
  return m;
}

}  // namespace fest::softobj_tool
