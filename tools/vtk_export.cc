#include "tools/vtk_export.h"

#include <algorithm>
#include <sstream>
#include <vector>

#include "core/error.h"

namespace tbridge::cli {

namespace {

std::string Piece(const DynamicModel& model, const Eigen::Matrix3Xd& p) {
  std::ostringstream out;
  out.precision(10);
  const size_t lines = model.bars.size() + model.strings.size();
  out << "<?xml version=\"1.0\"?>\n"
      << "<VTKFile type=\"PolyData\" version=\"0.1\" byte_order=\"LittleEndian\">\n<PolyData>\n"
      << "<Piece NumberOfPoints=\"" << model.num_nodes() << "\" NumberOfVerts=\"0\" NumberOfLines=\""
      << lines << "\" NumberOfStrips=\"0\" NumberOfPolys=\"0\">\n";
  out << "<Points>\n<DataArray type=\"Float64\" NumberOfComponents=\"3\" format=\"ascii\">\n";
  for (int v = 0; v < model.num_nodes(); ++v) out << p(0, v) << " " << p(1, v) << " " << p(2, v) << "\n";
  out << "</DataArray>\n</Points>\n";
  out << "<PointData Vectors=\"displacement\">\n"
      << "<DataArray type=\"Float64\" Name=\"displacement\" NumberOfComponents=\"3\" format=\"ascii\">\n";
  for (int v = 0; v < model.num_nodes(); ++v) {
    const Eigen::Vector3d u = p.col(v) - model.positions.col(v);
    out << u.x() << " " << u.y() << " " << u.z() << "\n";
  }
  out << "</DataArray>\n</PointData>\n";
  out << "<Lines>\n<DataArray type=\"Int32\" Name=\"connectivity\" format=\"ascii\">\n";
  for (const DynamicBar& b : model.bars) out << b.i << " " << b.j << "\n";
  for (const DynamicString& s : model.strings) out << s.i << " " << s.j << "\n";
  out << "</DataArray>\n<DataArray type=\"Int32\" Name=\"offsets\" format=\"ascii\">\n";
  for (size_t k = 1; k <= lines; ++k) out << 2 * k << "\n";
  out << "</DataArray>\n</Lines>\n";
  std::ostringstream type, tension, slack;
  tension.precision(10);
  for (size_t b = 0; b < model.bars.size(); ++b) {
    type << "0\n";
    tension << "0\n";
    slack << "0\n";
  }
  for (size_t k = 0; k < model.strings.size(); ++k) {
    const DynamicString s = model.strings[k];
    const double length = (p.col(s.j) - p.col(s.i)).norm();
    const bool is_slack = length < s.rest_length;
    type << (model.names.string_group[k] == "deck" ? 2 : 1) << "\n";
    tension << (is_slack ? 0.0 : s.stiffness * (length - s.rest_length)) << "\n";
    slack << (is_slack ? 1 : 0) << "\n";
  }
  out << "<CellData Scalars=\"tension_N\">\n"
      << "<DataArray type=\"Int32\" Name=\"member_type\" format=\"ascii\">\n" << type.str() << "</DataArray>\n"
      << "<DataArray type=\"Float64\" Name=\"tension_N\" format=\"ascii\">\n" << tension.str() << "</DataArray>\n"
      << "<DataArray type=\"Int32\" Name=\"slack\" format=\"ascii\">\n" << slack.str() << "</DataArray>\n"
      << "</CellData>\n</Piece>\n</PolyData>\n</VTKFile>\n";
  return out.str();
}

}  // namespace

void VtkHistory::Begin(const DynamicModel& model, const std::vector<int>& recorded_nodes) {
  for (int v = 0; v < model.num_nodes(); ++v) {
    if (model.fixed[v]) continue;
    if (std::find(recorded_nodes.begin(), recorded_nodes.end(), v) == recorded_nodes.end()) {
      throw ConfigError("dynamics.record.nodes", "(node " + std::to_string(v + 1) + " missing)",
                        "the VTK export needs every free node recorded");
    }
  }
  model_ = &model;
  recorded_ = recorded_nodes;
  positions_ = model.positions;
  pvd_.precision(12);
  pvd_ << "<?xml version=\"1.0\"?>\n<VTKFile type=\"Collection\" version=\"0.1\">\n<Collection>\n";
}

void VtkHistory::Row(double t, const double* coordinates) {
  const int dim = model_->dim;
  for (size_t k = 0; k < recorded_.size(); ++k) {
    for (int d = 0; d < dim; ++d) positions_(d, recorded_[k]) = coordinates[k * dim + d];
  }
  const std::string name = "run_" + std::to_string(samples_++) + ".vtp";
  emit_(name, Piece(*model_, positions_));
  pvd_ << "<DataSet timestep=\"" << t << "\" part=\"0\" file=\"" << name << "\"/>\n";
}

void VtkHistory::Finish() {
  if (samples_ == 0) {
    throw ConfigError("dynamics.record.nodes", "[]", "the VTK export needs recorded nodes: list every free node");
  }
  pvd_ << "</Collection>\n</VTKFile>\n";
}

double VtkBytesPerSample(const DynamicModel& model) {
  // Fixed XML of a piece and its pvd line ~1 kB; per node two rows of three 10-digit numbers
  // (~ 2 x 3 x 18 B); per member its connectivity, offset, type, tension and slack (~ 60 B).
  const double members = static_cast<double>(model.bars.size() + model.strings.size());
  return 1000.0 + 108.0 * model.num_nodes() + 60.0 * members;
}

}  // namespace tbridge::cli
