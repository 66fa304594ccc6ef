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

TriMesh marching_cubes(const softobj::Field& field, double iso, double rho, double h, std::size_t max_vertices,
                       std::size_t* dropped) {
  const auto& c = field.skeleton();
  Eigen::Vector3d lo0 = Eigen::Vector3d::Constant(1e300), hi0 = -lo0;
  for (const auto& t : c.terms)
    for (const auto& v : t.v) lo0 = lo0.cwiseMin(v), hi0 = hi0.cwiseMax(v);
  // The box grows by rho + 2h; overlapping primitives (a skeleton folding over itself)
  // push the surface further out, so the box grows until no sample on its faces reaches
  // the iso value (an open mesh otherwise).
  vtkNew<vtkImageData> img;
  vtkNew<vtkDoubleArray> values;
  for (double grow = rho + 2 * h;; grow *= 1.5) {
    Eigen::Vector3d lo = lo0.array() - grow, hi = hi0.array() + grow;
    int n[3];
    double cells = 1;
    for (int k = 0; k < 3; ++k) n[k] = static_cast<int>(std::ceil((hi[k] - lo[k]) / h)) + 1, cells *= n[k];
    if (cells > 4e8) throw runtime_failure("a grid of {} x {} x {} samples is too large", n[0], n[1], n[2]);
    img->SetDimensions(n[0], n[1], n[2]);
    img->SetOrigin(lo.x(), lo.y(), lo.z());
    img->SetSpacing(h, h, h);
    values->SetName("f");
    values->SetNumberOfTuples(static_cast<vtkIdType>(cells));
    vtkIdType id = 0;
    bool boundary_inside = false;
    for (int z = 0; z < n[2]; ++z)
      for (int y = 0; y < n[1]; ++y)
        for (int x = 0; x < n[0]; ++x) {
          const double v = field.value(lo + h * Eigen::Vector3d(x, y, z));
          values->SetValue(id++, v);
          if (v >= iso && (x == 0 || y == 0 || z == 0 || x == n[0] - 1 || y == n[1] - 1 || z == n[2] - 1))
            boundary_inside = true;
        }
    if (!boundary_inside) break;
  }
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
  std::size_t lost = 0;
  for (const auto& t : tris) {
    const auto f = s >= 0 ? m.add_face(vh[t[0]], vh[t[1]], vh[t[2]]) : m.add_face(vh[t[0]], vh[t[2]], vh[t[1]]);
    if (!f.is_valid()) ++lost;
  }
  if (dropped) *dropped = lost;
  return m;
}

}  // namespace fest::softobj_tool
