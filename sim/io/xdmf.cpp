// The XDMF sidecars that let ParaView open a run file (docs/FILE_FORMAT.md, "ParaView"): the
// frames in simulated time and the cycle ends, each step the sheet's surface and its hinge
// network with the plastic field and the crease mask.
#include "sim/io/xdmf.hpp"

#include "sim/core/errors.hpp"

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <sstream>

namespace crumple {

namespace {
// One XDMF time step (docs/FILE_FORMAT.md, "ParaView"): a spatial collection of the surface
// (triangles, node velocities when stored) and the hinge network (a polyline per hinge edge,
// its two nodes a hyperslab of /mesh/hinges, carrying p and the crease mask as cell data), with
// the cycle, the stage's code and the simulated time as field data of both.
struct XdmfStep {
  std::string name, group;  // the grid's name, the run file group holding x, p, crease (and v)
  double time = 0, t = 0;
  int cycle = 0, stage_code = 0;
  bool velocity = false;
};

void xdmf_field(std::ostream& out, const char* name, const std::string& number_type, double v) {
  out << "     <Attribute Name=\"" << name << "\" AttributeType=\"Scalar\" Center=\"Grid\">"
      << "<DataItem Dimensions=\"1\" NumberType=\"" << number_type
      << "\" Precision=\"8\" Format=\"XML\">" << std::setprecision(12) << v
      << "</DataItem></Attribute>\n";
}

void xdmf_step(std::ostream& out, const std::string& h5, const RunRecord& r, const XdmfStep& s) {
  const Index n = r.mesh.num_nodes(), tris = r.mesh.num_triangles(), hinges = r.mesh.num_hinges();
  auto heavy = [&](const std::string& dims, const char* type, int precision,
                   const std::string& path) {
    std::ostringstream os;
    os << "<DataItem Dimensions=\"" << dims << "\" NumberType=\"" << type << "\" Precision=\""
       << precision << "\" Format=\"HDF\">" << h5 << ":" << path << "</DataItem>";
    return os.str();
  };
  const std::string geometry = "     <Geometry GeometryType=\"XYZ\">" +
                               heavy(std::to_string(n) + " 3", "Float", 8, s.group + "/x") +
                               "</Geometry>\n";
  auto fields = [&] {
    xdmf_field(out, "cycle", "Int", s.cycle);
    xdmf_field(out, "stage_code", "Int", s.stage_code);
    xdmf_field(out, "t", "Float", s.t);
  };
  out << "   <Grid Name=\"" << s.name << "\" GridType=\"Collection\" CollectionType=\"Spatial\">\n"
      << "    <Time Value=\"" << std::setprecision(12) << s.time << "\"/>\n"
      << "    <Grid Name=\"surface\" GridType=\"Uniform\">\n"
      << "     <Topology TopologyType=\"Triangle\" NumberOfElements=\"" << tris << "\">"
      << heavy(std::to_string(tris) + " 3", "Int", 4, "/mesh/triangles") << "</Topology>\n"
      << geometry;
  if (s.velocity)
    out << "     <Attribute Name=\"velocity\" AttributeType=\"Vector\" Center=\"Node\">"
        << heavy(std::to_string(n) + " 3", "Float", 8, s.group + "/v") << "</Attribute>\n";
  fields();
  out << "    </Grid>\n"
      << "    <Grid Name=\"hinges\" GridType=\"Uniform\">\n"
      << "     <Topology TopologyType=\"Polyline\" NodesPerElement=\"2\" NumberOfElements=\""
      << hinges << "\">\n"
      << "      <DataItem ItemType=\"HyperSlab\" Dimensions=\"" << hinges << " 2\" Type=\"HyperSlab\">"
      << "<DataItem Dimensions=\"3 2\" Format=\"XML\">0 0 1 1 " << hinges << " 2</DataItem>"
      << heavy(std::to_string(hinges) + " 4", "Int", 4, "/mesh/hinges") << "</DataItem>\n"
      << "     </Topology>\n"
      << geometry
      << "     <Attribute Name=\"p\" AttributeType=\"Scalar\" Center=\"Cell\">"
      << heavy(std::to_string(hinges), "Float", 8, s.group + "/p") << "</Attribute>\n"
      << "     <Attribute Name=\"crease\" AttributeType=\"Scalar\" Center=\"Cell\">"
      << heavy(std::to_string(hinges), "UChar", 1, s.group + "/crease") << "</Attribute>\n";
  fields();
  out << "    </Grid>\n   </Grid>\n";
}
}  // namespace

void write_xdmf(const std::string& xdmf_path, const std::string& h5_name, const RunRecord& r,
                XdmfCollection collection) {
  // Stage codes in order of first appearance among the frames ("initial" first); the names are
  // in the file's Information element and in each step's name.
  std::vector<std::string> stages;
  auto code = [&](const std::string& stage) {
    const auto it = std::find(stages.begin(), stages.end(), stage);
    if (it != stages.end()) return static_cast<int>(it - stages.begin());
    stages.push_back(stage);
    return static_cast<int>(stages.size()) - 1;
  };
  std::vector<XdmfStep> steps;
  if (collection == XdmfCollection::Frames) {
    for (std::size_t k = 0; k < r.frames.size(); ++k) {
      const FrameRecord& f = r.frames[k];
      std::ostringstream name;
      name << "t=" << std::setprecision(6) << f.state.t << " s, cycle " << f.cycle << ", "
           << f.stage;
      steps.push_back({name.str(), "/frames/" + numbered(static_cast<long>(k), 6), f.state.t,
                       f.state.t, f.cycle, code(f.stage), true});
    }
  } else {
    for (const CycleRecord& c : r.cycles) {
      std::ostringstream name;
      name << "end of cycle " << c.cycle << ", t=" << std::setprecision(6) << c.t << " s";
      steps.push_back({name.str(), "/cycles/" + numbered(c.cycle, 4), double(c.cycle), c.t,
                       c.cycle, code("cycle end"), false});
    }
  }
  std::ofstream out(xdmf_path);
  if (!out) throw OutputError(xdmf_path + ": cannot create the XDMF file");
  out << "<?xml version=\"1.0\" ?>\n<Xdmf Version=\"3.0\">\n <Domain>\n";
  std::string codes;
  for (std::size_t k = 0; k < stages.size(); ++k) {
    if (k) codes += ", ";
    codes += std::to_string(k);
    codes += " ";
    codes += stages[k];
  }
  out << "  <Information Name=\"stage_code\" Value=\"" << codes << "\"/>\n"
      << "  <Information Name=\"time\" Value=\""
      << (collection == XdmfCollection::Frames ? "simulated time, s (/meta@time_note)"
                                               : "cycle number; the field t is the simulated time")
      << "\"/>\n"
      << "  <Grid Name=\"" << (collection == XdmfCollection::Frames ? "frames" : "cycles")
      << "\" GridType=\"Collection\" CollectionType=\"Temporal\">\n";
  for (const XdmfStep& s : steps) xdmf_step(out, h5_name, r, s);
  out << "  </Grid>\n </Domain>\n</Xdmf>\n";
  out.close();
  if (!out) {
    std::error_code ec;
    std::filesystem::remove(xdmf_path, ec);
    throw OutputError(xdmf_path + ": cannot write the XDMF file (disk full?)");
  }
}


}  // namespace crumple
