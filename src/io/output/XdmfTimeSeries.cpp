#include "io/output/XdmfTimeSeries.hpp"

#include <sstream>

#include "io/output/RoundTripText.hpp"

namespace glossa::io {

namespace {
// Field and file names go into XML attributes and text; escape the five special characters.
std::string xmlEscaped(const std::string &text) {
  std::string out;
  out.reserve(text.size());
  for (const char c : text) {
    switch (c) {
    case '&': out += "&amp;"; break;
    case '<': out += "&lt;"; break;
    case '>': out += "&gt;"; break;
    case '"': out += "&quot;"; break;
    case '\'': out += "&apos;"; break;
    default: out += c;
    }
  }
  return out;
}

std::string dimensions(std::size_t rows, int columns) {
  return columns == 1 ? std::to_string(rows) : std::to_string(rows) + " " + std::to_string(columns);
}

void dataItem(std::ostringstream &x, const std::string &indent, const std::string &dims, const char *numberType,
              const std::string &file, const std::string &dataset) {
  x << indent << "<DataItem Dimensions=\"" << dims << "\" NumberType=\"" << numberType
    << "\" Precision=\"8\" Format=\"HDF\">" << xmlEscaped(file) << ':' << xmlEscaped(dataset) << "</DataItem>\n";
}

// Topology and geometry of one grid; every step repeats them (they point at the same datasets).
void meshItems(std::ostringstream &x, const XdmfMesh &mesh, const std::string &indent) {
  x << indent << "<Topology TopologyType=\"Hexahedron\" NumberOfElements=\"" << mesh.numCells << "\">\n";
  dataItem(x, indent + "  ", dimensions(mesh.numCells, 8), "Int", mesh.heavyDataFile, mesh.topologyDataset);
  x << indent << "</Topology>\n" << indent << "<Geometry GeometryType=\"XYZ\">\n";
  dataItem(x, indent + "  ", dimensions(mesh.numNodes, 3), "Float", mesh.heavyDataFile, mesh.coordinatesDataset);
  x << indent << "</Geometry>\n";
}

void attributeItem(std::ostringstream &x, const XdmfMesh &mesh, const std::string &file, const XdmfAttribute &a,
                   const std::string &indent) {
  const bool node = a.center == Centering::Node;
  x << indent << "<Attribute Name=\"" << xmlEscaped(a.name) << "\" AttributeType=\"" << xdmfAttributeType(a.components)
    << "\" Center=\"" << (node ? "Node" : "Cell") << "\">\n";
  dataItem(x, indent + "  ", dimensions(node ? mesh.numNodes : mesh.numCells, a.components), "Float", file,
           a.dataset);
  x << indent << "</Attribute>\n";
}
} // namespace

const char *xdmfAttributeType(int components) {
  switch (components) {
  case 1: return "Scalar";
  case 3: return "Vector";
  case 6: return "Tensor6";
  case 9: return "Tensor";
  default: return nullptr;
  }
}

std::string composeXdmfTimeSeries(const XdmfMesh &mesh, const std::vector<XdmfStep> &steps) {
  std::ostringstream x;
  x << "<?xml version=\"1.0\" ?>\n"
    << "<Xdmf Version=\"3.0\" xmlns:xi=\"http://www.w3.org/2001/XInclude\">\n"
    << "  <Domain>\n";
  if (steps.empty()) {
    x << "    <Grid Name=\"mesh\" GridType=\"Uniform\">\n";
    meshItems(x, mesh, "      ");
    x << "    </Grid>\n";
  } else {
    x << "    <Grid Name=\"time series\" GridType=\"Collection\" CollectionType=\"Temporal\">\n";
    for (std::size_t i = 0; i < steps.size(); ++i) {
      x << "      <Grid Name=\"step " << i << "\" GridType=\"Uniform\">\n"
        << "        <Time Value=\"" << roundTripText(steps[i].time) << "\"/>\n";
      meshItems(x, mesh, "        ");
      const std::string &file = steps[i].heavyDataFile.empty() ? mesh.heavyDataFile : steps[i].heavyDataFile;
      for (const auto &a : steps[i].attributes) attributeItem(x, mesh, file, a, "        ");
      x << "      </Grid>\n";
    }
    x << "    </Grid>\n";
  }
  x << "  </Domain>\n</Xdmf>\n";
  return x.str();
}

} // namespace glossa::io
