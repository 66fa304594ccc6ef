// The constraint calculus of docs/lmfsim.md §2. Notation: anchor P = p + w with w = R r;
// Pdot = v + omega x w; the part of Pddot not linear in (a, alpha) is omega x (omega x w).
// Each row is written as C, dC/dt = J xdot (+ dC/dt explicit), J, and c such that
// Cddot = J xdd + c.
#include "lmfsim/constraint_eval.hpp"

namespace fest::lmfsim {
namespace {

struct Anchor {
  Vec3 w, P, Pdot, acc;  // acc = omega x (omega x w)
};

Anchor anchor(const BodyKin& k, const Vec3& r) {
  Anchor a;
  a.w = k.R * r;
  a.P = k.p + a.w;
  a.Pdot = k.v + k.w.cross(a.w);
  a.acc = k.w.cross(k.w.cross(a.w));
  return a;
}

// Row "n . P_a" style: linear n, angular w x n.
void point_row(Blk& J, int row, const Vec3& n, const Vec3& w, double sign) {
  J.block<1, 3>(row, 0) = sign * n.transpose();
  J.block<1, 3>(row, 3) = sign * w.cross(n).transpose();
}

// C = u_a . t_b for unit vectors u on a and t on b (hinge/axis_parallel extra rows).
void dot_row(ConstraintEval& e, int row, const Vec3& u, const Vec3& t, const BodyKin& ka, const BodyKin& kb) {
  const Vec3 uxt = u.cross(t);
  e.C[row] = u.dot(t);
  e.Cdot[row] = uxt.dot(ka.w - kb.w);
  e.Ja.block<1, 3>(row, 3) = uxt.transpose();
  e.Jb.block<1, 3>(row, 3) = -uxt.transpose();
  e.c[row] = ka.w.cross(ka.w.cross(u)).dot(t) + 2 * ka.w.cross(u).dot(kb.w.cross(t)) + u.dot(kb.w.cross(kb.w.cross(t)));
}

void ball_rows(ConstraintEval& e, int row, const Anchor& A, const Anchor& B) {
  e.C.segment<3>(row) = A.P - B.P;
  e.Cdot.segment<3>(row) = A.Pdot - B.Pdot;
  e.Ja.block<3, 3>(row, 0) = Mat3::Identity();
  e.Ja.block<3, 3>(row, 3) = -skew(A.w);
  e.Jb.block<3, 3>(row, 0) = -Mat3::Identity();
  e.Jb.block<3, 3>(row, 3) = skew(B.w);
  e.c.segment<3>(row) = A.acc - B.acc;
}

// Orientation lock: C = 2 vec(e), e = q_a (q_b q0)^-1 with e_w >= 0; J ang a = I,
// ang b = -I, c = 0 (first-order, docs/lmfsim.md §2).
void orientation_rows(ConstraintEval& e, int row, const Constraint& c, const BodyKin& ka, const BodyKin& kb) {
  const Quat qa(ka.R), qb(kb.R);
  Quat err = qa * (qb * c.rest).conjugate();
  if (err.w() < 0) err.coeffs() = -err.coeffs();
  e.C.segment<3>(row) = 2 * err.vec();
  e.Cdot.segment<3>(row) = ka.w - kb.w;
  e.Ja.block<3, 3>(row, 3) = Mat3::Identity();
  e.Jb.block<3, 3>(row, 3) = -Mat3::Identity();
  e.c.segment<3>(row).setZero();
}

}  // namespace

void eval_constraint(const Constraint& c, const BodyKin& ka, const BodyKin& kb, double t, ConstraintEval& e) {
  const int m = constraint_rows(c.type);
  e.rows = m;
  if (c.type == ConstraintType::ball) {
    // ball_rows writes every entry; zeroing first cost five memset calls per joint
    // per evaluation, a visible share of a long chain's step.
    e.C.resize(m);
    e.Cdot.resize(m);
    e.c.resize(m);
    e.Ja.resize(m, 6);
    e.Jb.resize(m, 6);
  } else {
    e.C.setZero(m);
    e.Cdot.setZero(m);
    e.c.setZero(m);
    e.Ja.setZero(m, 6);
    e.Jb.setZero(m, 6);
  }
  const Anchor A = anchor(ka, c.pa), B = anchor(kb, c.pb);
  switch (c.type) {
    case ConstraintType::ball: ball_rows(e, 0, A, B); break;
    case ConstraintType::hinge:
    case ConstraintType::axis_parallel: {
      const int row = c.type == ConstraintType::hinge ? 3 : 0;
      if (row) ball_rows(e, 0, A, B);
      Vec3 t1, t2;
      perpendiculars(c.axis_b, t1, t2);
      const Vec3 u = ka.R * c.axis_a;
      dot_row(e, row, u, kb.R * t1, ka, kb);
      dot_row(e, row + 1, u, kb.R * t2, ka, kb);
      break;
    }
    case ConstraintType::weld:
      ball_rows(e, 0, A, B);
      orientation_rows(e, 3, c, ka, kb);
      break;
    case ConstraintType::slider: {
      orientation_rows(e, 0, c, ka, kb);
      Vec3 t1, t2;
      perpendiculars(c.axis_a, t1, t2);
      const Vec3 d = B.P - A.P, dd = B.Pdot - A.Pdot;
      for (int k = 0; k < 2; ++k) {
        const Vec3 tk = ka.R * (k == 0 ? t1 : t2);
        const int r = 3 + k;
        e.C[r] = tk.dot(d);
        e.Cdot[r] = ka.w.cross(tk).dot(d) + tk.dot(dd);
        e.Ja.block<1, 3>(r, 0) = -tk.transpose();
        e.Ja.block<1, 3>(r, 3) = tk.cross(d + A.w).transpose();
        e.Jb.block<1, 3>(r, 0) = tk.transpose();
        e.Jb.block<1, 3>(r, 3) = B.w.cross(tk).transpose();
        e.c[r] = ka.w.cross(ka.w.cross(tk)).dot(d) + 2 * ka.w.cross(tk).dot(dd) + tk.dot(B.acc - A.acc);
      }
      break;
    }
    case ConstraintType::distance: {
      const Vec3 d = B.P - A.P, dd = B.Pdot - A.Pdot;
      e.C[0] = 0.5 * (d.squaredNorm() - c.length * c.length);
      e.Cdot[0] = d.dot(dd);
      point_row(e.Ja, 0, d, A.w, -1);
      point_row(e.Jb, 0, d, B.w, 1);
      e.c[0] = dd.squaredNorm() + d.dot(B.acc - A.acc);
      break;
    }
    case ConstraintType::point_on_plane: {
      const Vec3& n = c.direction;
      e.C[0] = n.dot(A.P - c.origin);
      e.Cdot[0] = n.dot(A.Pdot);
      point_row(e.Ja, 0, n, A.w, 1);
      e.c[0] = n.dot(A.acc);
      break;
    }
    case ConstraintType::point_on_line: {
      Vec3 t1, t2;
      perpendiculars(c.direction, t1, t2);
      for (int k = 0; k < 2; ++k) {
        const Vec3& tk = k == 0 ? t1 : t2;
        e.C[k] = tk.dot(A.P - c.origin);
        e.Cdot[k] = tk.dot(A.Pdot);
        point_row(e.Ja, k, tk, A.w, 1);
        e.c[k] = tk.dot(A.acc);
      }
      break;
    }
    case ConstraintType::point_on_circle: {
      const Vec3& n = c.direction;
      const Vec3 r = A.P - c.origin;
      e.C[0] = n.dot(r);
      e.Cdot[0] = n.dot(A.Pdot);
      point_row(e.Ja, 0, n, A.w, 1);
      e.c[0] = n.dot(A.acc);
      e.C[1] = 0.5 * (r.squaredNorm() - c.radius * c.radius);
      e.Cdot[1] = r.dot(A.Pdot);
      point_row(e.Ja, 1, r, A.w, 1);
      e.c[1] = A.Pdot.squaredNorm() + r.dot(A.acc);
      break;
    }
    case ConstraintType::path: {
      e.C.segment<3>(0) = A.P - c.path.at(t);
      e.Cdot.segment<3>(0) = A.Pdot - c.path.rate(t);
      e.Ja.block<3, 3>(0, 0) = Mat3::Identity();
      e.Ja.block<3, 3>(0, 3) = -skew(A.w);
      e.c.segment<3>(0) = A.acc - c.path.accel(t);
      break;
    }
    case ConstraintType::motor: {
      const Vec3 u = ka.R * c.axis_a, rel = kb.w - ka.w;
      e.C[0] = u.dot(rel) - c.omega.at(t);
      e.Cdot[0] = 0;  // velocity row: C itself is the velocity error
      e.Ja.block<1, 3>(0, 3) = -u.transpose();
      e.Jb.block<1, 3>(0, 3) = u.transpose();
      e.c[0] = ka.w.cross(u).dot(rel) - c.omega.rate(t);
      break;
    }
    case ConstraintType::knife_edge: {
      const Vec3 n = ka.R * c.axis_a;
      e.C[0] = n.dot(A.Pdot);
      e.Cdot[0] = 0;
      point_row(e.Ja, 0, n, A.w, 1);
      e.c[0] = ka.w.cross(n).dot(A.Pdot) + n.dot(A.acc);
      break;
    }
  }
}

}  // namespace fest::lmfsim
