#include "tools/vtk_export.h"

#include <algorithm>
#include <bit>
#include <cstdio>

#include "core/error.h"

namespace tbridge::cli {

namespace {

// run.xdmf declares its arrays little-endian 4-byte integers and 8-byte floats, as written.
static_assert(std::endian::native == std::endian::little && sizeof(int) == 4 &&
              sizeof(double) == 8);

template <class T>
void WriteRaw(std::ostream& out, const std::vector<T>& values) {
  out.write(reinterpret_cast<const char*>(values.data()),
            static_cast<std::streamsize>(values.size() * sizeof(T)));
}

}  // namespace

void VtkHistory::Item(const char* dimensions, bool real, long long offset) {
  char text[256];
  std::snprintf(text, sizeof text,
                "<DataItem Format=\"Binary\" Endian=\"Little\" NumberType=\"%s\" Precision=\"%d\" "
                "Dimensions=\"%s\" Seek=\"%lld\">run.bin</DataItem>",
                real ? "Float" : "Int", real ? 8 : 4, dimensions, offset);
  xml_ << text;
}

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
  const size_t nodes = static_cast<size_t>(model.num_nodes()),
               members = model.bars.size() + model.strings.size();
  points_.resize(3 * nodes);
  displacement_.resize(3 * nodes);
  tension_.assign(members, 0.0);
  slack_.assign(members, 0);
  // The constant head of run.bin: connectivity, then member types.
  std::vector<int> connectivity, types;
  for (const DynamicBar& b : model.bars)
    connectivity.insert(connectivity.end(), {b.i, b.j}), types.push_back(0);
  for (size_t k = 0; k < model.strings.size(); ++k) {
    connectivity.insert(connectivity.end(), {model.strings[k].i, model.strings[k].j});
    types.push_back(model.names.string_group[k] == MemberGroup::kDeck ? 2 : 1);
  }
  WriteRaw(bin_, connectivity);
  types_offset_ = static_cast<long long>(connectivity.size() * sizeof(int));
  WriteRaw(bin_, types);
  offset_ = types_offset_ + static_cast<long long>(types.size() * sizeof(int));
  xml_ << "<?xml version=\"1.0\"?>\n<Xdmf Version=\"2.0\">\n<Domain>\n"
       << "<Grid Name=\"run\" GridType=\"Collection\" CollectionType=\"Temporal\">\n";
}

void VtkHistory::Row(double t, const double* coordinates) {
  const DynamicModel& model = *model_;
  const int dim = model.dim;
  for (size_t k = 0; k < recorded_.size(); ++k) {
    for (int d = 0; d < dim; ++d) positions_(d, recorded_[k]) = coordinates[k * dim + d];
  }
  const int nodes = model.num_nodes();
  for (int v = 0; v < nodes; ++v) {
    for (int a = 0; a < 3; ++a) {
      points_[3 * v + a] = positions_(a, v);
      displacement_[3 * v + a] = positions_(a, v) - model.positions(a, v);
    }
  }
  const size_t nb = model.bars.size();
  for (size_t k = 0; k < model.strings.size(); ++k) {
    const DynamicString& s = model.strings[k];
    const double length = (positions_.col(s.j) - positions_.col(s.i)).norm();
    const bool is_slack = length < s.rest_length;
    tension_[nb + k] = is_slack ? 0.0 : s.stiffness * (length - s.rest_length);
    slack_[nb + k] = is_slack ? 1 : 0;
  }
  const long long points_at = offset_, displacement_at = points_at + 24LL * nodes;
  const long long tension_at = displacement_at + 24LL * nodes;
  const long long slack_at = tension_at + 8LL * static_cast<long long>(tension_.size());
  WriteRaw(bin_, points_);
  WriteRaw(bin_, displacement_);
  WriteRaw(bin_, tension_);
  WriteRaw(bin_, slack_);
  offset_ = slack_at + 4LL * static_cast<long long>(slack_.size());

  const std::string members = std::to_string(tension_.size()),
                    node_rows = std::to_string(nodes) + " 3";
  char head[160];
  std::snprintf(head, sizeof head,
                "<Grid Name=\"sample %ld\" GridType=\"Uniform\">\n<Time Value=\"%.12g\"/>\n",
                samples_++, t);
  xml_ << head << "<Topology TopologyType=\"Polyline\" NodesPerElement=\"2\" NumberOfElements=\""
       << members << "\">";
  Item((members + " 2").c_str(), false, 0);
  xml_ << "</Topology>\n<Geometry GeometryType=\"XYZ\">";
  Item(node_rows.c_str(), true, points_at);
  xml_ << "</Geometry>\n<Attribute Name=\"displacement\" AttributeType=\"Vector\" Center=\"Node\">";
  Item(node_rows.c_str(), true, displacement_at);
  xml_ << "</Attribute>\n<Attribute Name=\"member_type\" AttributeType=\"Scalar\" Center=\"Cell\">";
  Item(members.c_str(), false, types_offset_);
  xml_ << "</Attribute>\n<Attribute Name=\"tension_N\" AttributeType=\"Scalar\" Center=\"Cell\">";
  Item(members.c_str(), true, tension_at);
  xml_ << "</Attribute>\n<Attribute Name=\"slack\" AttributeType=\"Scalar\" Center=\"Cell\">";
  Item(members.c_str(), false, slack_at);
  xml_ << "</Attribute>\n</Grid>\n";
}

void VtkHistory::Finish() {
  if (samples_ == 0) {
    throw ConfigError("dynamics.record.nodes", "[]",
                      "the VTK export needs recorded nodes: list every free node");
  }
  xml_ << "</Grid>\n</Domain>\n</Xdmf>\n";
}

double VtkBytesPerSample(const DynamicModel& model) {
  // A grid's XML ~1.3 kB; per node its position and displacement (48 B); per member its
  // tension and slack flag (12 B).
  const double members = static_cast<double>(model.bars.size() + model.strings.size());
  return 1300.0 + 48.0 * model.num_nodes() + 12.0 * members;
}

}  // namespace tbridge::cli
