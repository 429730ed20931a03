#include "solvers/run/AirwayRecorder.hpp"

#include <cstdio>
#include <fstream>
#include <iomanip>
#include <limits>
#include <sstream>
#include <string>

#include "io/output/OutputError.hpp"

namespace glossa::solvers {

namespace {
std::string twoDigits(std::size_t k) {
  char s[24]; // room for any size_t: no truncation warning
  std::snprintf(s, sizeof s, "%02zu", k);
  return s;
}

std::string outlineFile(std::size_t step) {
  char s[32];
  std::snprintf(s, sizeof s, "step_%06zu.vtk", step);
  return s;
}

std::vector<std::string> columns(std::size_t sections) {
  std::vector<std::string> c;
  for (std::size_t k = 0; k < sections; ++k) c.push_back("area_" + twoDigits(k) + " [m^2]");
  for (const char *name : {"smallest_area [m^2]", "smallest_section [-]", "smallest_arc_length [m]",
                           "contact_area [m^2]", "closed [-]", "closed_sections [-]"})
    c.emplace_back(name);
  return c;
}

// Written whole to a temporary name and renamed into place, so a reader never sees half a file.
void writeFile(const std::filesystem::path &file, const std::string &text) {
  const std::filesystem::path tmp = file.string() + ".tmp";
  {
    std::ofstream out(tmp, std::ios::binary);
    out << text;
    if (!out.flush()) throw io::OutputError("cannot write " + tmp.string());
  }
  std::filesystem::rename(tmp, file);
}

// The times of airway.csv's rows, as kept after a restart's cut-back.
std::vector<double> rowTimes(const std::filesystem::path &csv) {
  std::vector<double> times;
  std::ifstream in(csv);
  std::string line;
  std::getline(in, line);  // the header
  while (std::getline(in, line))
    if (!line.empty()) times.push_back(std::stod(line.substr(0, line.find(','))));
  return times;
}
}  // namespace

AirwayRecorder::AirwayRecorder(const model::AirwayOutput &airway, const std::filesystem::path &dir,
                               std::optional<std::uintmax_t> resumeAt)
    : airway_(airway), dir_(dir) {
  csv_ = std::make_unique<io::KeyedCsvWriter>(dir / "airway.csv", "lumen", columns(airway.lumen->numSections()),
                                              resumeAt);
  std::filesystem::create_directories(dir / "airway_sections");
  if (resumeAt) times_ = rowTimes(dir / "airway.csv");
  writeSectionsTable();
}

void AirwayRecorder::writeSectionsTable() const {
  const airway::Centreline &c = airway_.lumen->centreline();
  std::ostringstream s;
  s << std::setprecision(17)
    << "section,arc_length [m],centre_x [m],centre_y [m],centre_z [m],normal_x [-],normal_y [-],normal_z [-]\n";
  for (std::size_t k = 0; k < c.planes.size(); ++k) {
    const auto &p = c.planes[k];
    s << k << ',' << c.arcLength[k] << ',' << p.origin.x() << ',' << p.origin.y() << ',' << p.origin.z() << ','
      << p.normal.x() << ',' << p.normal.y() << ',' << p.normal.z() << '\n';
  }
  writeFile(dir_ / "airway_sections.csv", s.str());
}

void AirwayRecorder::record(double time, const std::vector<Eigen::Vector3d> &positions,
                            const std::vector<contact::ContactMeasures> &contacts) {
  const airway::LumenState state = airway_.lumen->measure(positions);
  std::vector<double> row;
  for (const auto &section : state.sections) row.push_back(section.area());
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const int k = state.smallest;
  row.push_back(k < 0 ? nan : state.sections[static_cast<std::size_t>(k)].area());
  row.push_back(k < 0 ? nan : static_cast<double>(k));
  row.push_back(k < 0 ? nan : airway_.lumen->centreline().arcLength[static_cast<std::size_t>(k)]);
  const auto c = static_cast<std::size_t>(airway_.contact);
  row.push_back(airway_.contact >= 0 && c < contacts.size() ? contacts[c].area : 0.0);
  row.push_back(state.closed() ? 1.0 : 0.0);
  row.push_back(static_cast<double>(state.closedSections));
  csv_->append(time, {{"airway", row}});
  writeOutlines(state);
  times_.push_back(time);
  writeSeries();
}

void AirwayRecorder::writeOutlines(const airway::LumenState &state) const {
  const auto &planes = airway_.lumen->centreline().planes;
  std::ostringstream points, lines, area, closed, index;
  std::size_t nPoints = 0, nLines = 0, nEntries = 0;
  points << std::setprecision(17);
  area << std::setprecision(17);
  for (std::size_t k = 0; k < state.sections.size(); ++k) {
    const auto &outline = state.sections[k].lumen.outline;
    if (!state.sections[k].measured || outline.size() < 2) continue;
    lines << outline.size() + 1;
    for (std::size_t p = 0; p < outline.size(); ++p) {
      const Eigen::Vector3d x = planes[k].at(outline[p]);
      points << x.x() << ' ' << x.y() << ' ' << x.z() << '\n';
      lines << ' ' << nPoints + p;
    }
    lines << ' ' << nPoints << '\n';  // closed: back to its first point
    nPoints += outline.size();
    nEntries += outline.size() + 2;
    ++nLines;
    area << state.sections[k].lumen.area << '\n';
    closed << (state.sections[k].closed ? 1 : 0) << '\n';
    index << k << '\n';
  }
  std::ostringstream s;
  s << "# vtk DataFile Version 3.0\nGlossa airway sections\nASCII\nDATASET POLYDATA\nPOINTS " << nPoints
    << " double\n"
    << points.str() << "LINES " << nLines << ' ' << nEntries << '\n'
    << lines.str() << "CELL_DATA " << nLines << "\nSCALARS area double 1\nLOOKUP_TABLE default\n"
    << area.str() << "SCALARS closed int 1\nLOOKUP_TABLE default\n"
    << closed.str() << "SCALARS section int 1\nLOOKUP_TABLE default\n"
    << index.str();
  writeFile(dir_ / "airway_sections" / outlineFile(times_.size()), s.str());
}

void AirwayRecorder::writeSeries() const {
  std::ostringstream s;
  s << std::setprecision(17) << "{\n  \"file-series-version\": \"1.0\",\n  \"files\": [\n";
  for (std::size_t k = 0; k < times_.size(); ++k)
    s << "    {\"name\": \"airway_sections/" << outlineFile(k) << "\", \"time\": " << times_[k] << '}'
      << (k + 1 < times_.size() ? "," : "") << '\n';
  s << "  ]\n}\n";
  writeFile(dir_ / "airway_sections.vtk.series", s.str());
}

}  // namespace glossa::solvers
