// ffd: free-form deformation of meshes by a control lattice (Sederberg & Parry), with
// exact joint preservation, rigid objects and animation (docs/ffd.md). Flags only; the
// subcommands live in cmd_<sub>.cpp.

#include <OpenMesh/Core/System/omstream.hh>

#include <string>
#include <vector>

#include "cli/cli.hpp"
#include "cli/enum_option.hpp"
#include "commands.hpp"

namespace {

using namespace fest::ffd_tool;

// --outside of apply, jacobian and animate: none (points outside the box stay) or clamp.
void add_outside(CLI::App* cmd, fest::ffd::Outside& outside, const char* help) {
  fest::cli::word_option(*cmd, "--outside", outside,
                         {{"none", fest::ffd::Outside::none}, {"clamp", fest::ffd::Outside::clamp}}, help);
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"Free-form deformation of meshes by a trivariate control lattice (Bernstein, B-spline, linear,\n"
               "Catmull-Rom), joints kept exactly on their targets, rigid and deformable objects in one lattice.",
               "ffd"};
  fest::cli::Common common;
  fest::cli::add_common(app, common);
  app.require_subcommand(1);

  InitOptions init;
  CLI::App* si = app.add_subcommand("init", "Fit an undeformed lattice box around a mesh; lattice JSON out");
  si->add_option("input", init.input, "Mesh (- : standard input)");
  si->add_option("-o,--output", init.output, "Lattice JSON (- : standard output)");
  si->add_option("--dims", init.dims, "Control points per axis L,M,N")->delimiter(',')->expected(3)->allow_extra_args(false)->check(fest::cli::range(2, 64));
  si->add_option_function<std::string>(
      "--basis", [&init](const std::string& name) { init.basis = fest::ffd::basis_from_name(name.c_str()); },
      "bernstein, bspline, linear or catmull-rom");
  si->add_option("--pad", init.pad, "Box growth per side as a fraction of the extent");

  ApplyOptions ap;
  CLI::App* sa = app.add_subcommand("apply", "Deform meshes with a lattice (JSON or PyGeM .prm)");
  sa->add_option("input", ap.input, "Mesh (- : standard input), when no --in is given");
  sa->add_option("-o,--output", ap.output, "Output mesh; with several objects a pattern with %s (the name)");
  sa->add_option("--lattice", ap.lattice, "Lattice file: JSON or PyGeM .prm")->required();
  sa->add_option_function<std::vector<std::string>>(
      "--in",
      [&ap](const std::vector<std::string>& specs) {
        for (const std::string& spec : specs) {
          const std::size_t eq = spec.find('=');
          if (eq == std::string::npos || eq == 0) throw fest::usage_error("--in takes NAME=FILE ('{}')", spec);
          ap.inputs.push_back({spec.substr(0, eq), spec.substr(eq + 1)});
        }
      },
      "NAME=FILE: an object of its own (repeatable)");
  sa->add_option_function<std::vector<std::string>>(
      "--object",
      [&ap](const std::vector<std::string>& specs) {
        for (const std::string& spec : specs) {
          const std::size_t eq = spec.find('=');
          if (eq == std::string::npos) throw fest::usage_error("--object takes NAME=deform|rigid|ignore ('{}')", spec);
          const std::string name = spec.substr(0, eq), mode = spec.substr(eq + 1);
          if (mode == "deform") ap.objects.push_back({name, ObjectMode::deform});
          else if (mode == "rigid") ap.objects.push_back({name, ObjectMode::rigid});
          else if (mode == "ignore") ap.objects.push_back({name, ObjectMode::ignore});
          else throw fest::usage_error("--object {}: unknown mode '{}'", name, mode);
        }
      },
      "NAME=deform|rigid|ignore (repeatable)");
  sa->add_option("--joints", ap.joints, "Joints 'name x y z tx ty tz' kept exactly on their targets");
  sa->add_option("--fixed-cp", ap.fixed_cp, "Control points 'i j k' the joint correction must not move");
  add_outside(sa, ap.outside, "Points outside the box: none (unchanged) or clamp");
  fest::cli::word_option(*sa, "--normals", ap.normals,
                         {{"recompute", NormalsMode::recompute}, {"jacobian", NormalsMode::jacobian}},
                         "Vertex normals: recompute, or jacobian (J^-T n)");
  sa->add_option("--to", ap.to, "Output format (ply, off, obj, stl); default from -o, else the input's");
  sa->add_option("--report", ap.report, "JSON: joint errors, det J range, rigid-fit RMS, straddling faces, time");
  sa->add_flag("--strict", ap.strict, "More joints than the lattice can satisfy is an error");
  sa->add_flag("--allow-large", ap.allow_large, "Allow lattices above 64^3 control points");
  sa->add_flag("--ascii", ap.ascii, "ASCII PLY/STL output");
  fest::cli::add_threads(*sa, ap.threads);

  JacobianOptions jo;
  CLI::App* sj = app.add_subcommand("jacobian", "Per-vertex det J of the deformation (TSV: vertex, detJ)");
  sj->add_option("input", jo.input, "Mesh (- : standard input)");
  sj->add_option("-o,--output", jo.output, "TSV (- : standard output)");
  sj->add_option("--lattice", jo.lattice, "Lattice file")->required();
  add_outside(sj, jo.outside, "none or clamp");

  LatticeMeshOptions lm;
  CLI::App* sl = app.add_subcommand("lattice-mesh", "The control net as OBJ lines");
  sl->add_option("input", lm.input, "Lattice file (- : standard input)");
  sl->add_option("-o,--output", lm.output, "OBJ (- : standard output)");

  ConvertOptions cv;
  CLI::App* sc = app.add_subcommand("convert", "Lattice JSON <-> PyGeM .prm (input recognised by content)");
  sc->add_option("input", cv.input, "Lattice file (- : standard input)");
  sc->add_option("-o,--output", cv.output, "Output (- : standard output)");
  fest::cli::word_option(*sc, "--to", cv.to, {{"json", LatticeFormat::json}, {"pygem", LatticeFormat::pygem}},
                         "json or pygem");

  AnimateOptions an;
  CLI::App* sn = app.add_subcommand("animate", "Frames from key lattices, each deformed from the rest mesh");
  sn->add_option("input", an.input, "Rest mesh (- : standard input)");
  sn->add_option("--keys", an.keys, "TSV rows 'time lattice_file'")->required();
  sn->add_option("-o,--output", an.output, "Frame pattern, e.g. frames/f%04d.ply")->required();
  sn->add_option("--fps", an.fps, "Frames per second");
  sn->add_option("--manifest", an.manifest, "Manifest TSV (frame, time, file); - : standard output");
  add_outside(sn, an.outside, "none or clamp");
  fest::cli::add_threads(*sn, an.threads);
  fest::cli::add_progress(*sn, an.progress);

  app.footer("Exit status: 0 success, 1 failure (--strict joints, size limit), 2 usage error, 3 bad input, 4 I/O error.\n"
             "See ffd(1).");
  return fest::cli::run(app, argc, argv, [&] {
    ::omerr().disable();
    if (si->parsed()) return run_init(init);
    if (sa->parsed()) return run_apply(ap);
    if (sj->parsed()) return run_jacobian(jo);
    if (sl->parsed()) return run_lattice_mesh(lm);
    if (sc->parsed()) return run_convert(cv);
    return run_animate(an);
  });
}
