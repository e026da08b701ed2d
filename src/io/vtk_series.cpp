#include "cosserat/io/vtk_series.hpp"

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <sstream>
#include <system_error>

namespace cosserat::io {
namespace {

/// A point-data array of 3-vectors, one per node, computed by `value(node)`.
template <typename Value>
void VectorArray(std::ostream& out, const char* name, int nodes, const Value& value) {
  out << "        <DataArray type=\"Float64\" Name=\"" << name
      << "\" NumberOfComponents=\"3\" format=\"ascii\">\n         ";
  for (int i = 0; i < nodes; ++i) {
    const Vec3 v = value(i);
    out << ' ' << v.x() << ' ' << v.y() << ' ' << v.z();
  }
  out << "\n        </DataArray>\n";
}

template <typename Value>
void ScalarArray(std::ostream& out, const char* name, int nodes, const Value& value) {
  out << "        <DataArray type=\"Float64\" Name=\"" << name << "\" format=\"ascii\">\n         ";
  for (int i = 0; i < nodes; ++i) out << ' ' << value(i);
  out << "\n        </DataArray>\n";
}

void Piece(std::ostream& out, int rod, const RodState& st, const std::vector<double>& radius,
           const std::vector<Vec3>* contact_force) {
  const int n = st.size();
  out << "    <Piece NumberOfPoints=\"" << n
      << "\" NumberOfVerts=\"0\" NumberOfLines=\"1\" NumberOfStrips=\"0\" NumberOfPolys=\"0\">\n"
      << "      <PointData Scalars=\"radius\">\n";
  // Which rod the point is on (0-based, in the order of assembly.rods): to colour or threshold.
  out << "        <DataArray type=\"Int32\" Name=\"rod\" format=\"ascii\">\n         ";
  for (int i = 0; i < n; ++i) out << ' ' << rod;
  out << "\n        </DataArray>\n";
  ScalarArray(out, "s", n, [&](int i) { return st.s[i]; });
  ScalarArray(out, "radius", n, [&](int i) { return i < int(radius.size()) ? radius[i] : 0.0; });
  for (int j = 0; j < 3; ++j) {
    const char* names[] = {"d1", "d2", "d3"};
    VectorArray(out, names[j], n, [&](int i) { return Vec3(st.rotation_WB[i].col(j)); });
  }
  VectorArray(out, "curvature", n, [&](int i) { return Vec3(st.strain[i].head<3>()); });
  VectorArray(out, "shear_stretch", n, [&](int i) { return Vec3(st.strain[i].tail<3>()); });
  VectorArray(out, "force", n,
              [&](int i) { return Vec3(st.rotation_WB[i] * st.wrench_B[i].tail<3>()); });
  VectorArray(out, "moment", n,
              [&](int i) { return Vec3(st.rotation_WB[i] * st.wrench_B[i].head<3>()); });
  VectorArray(out, "velocity", n,
              [&](int i) { return Vec3(st.rotation_WB[i] * st.twist_B[i].tail<3>()); });
  if (contact_force && static_cast<int>(contact_force->size()) == n)
    VectorArray(out, "contact_force", n, [&](int i) { return (*contact_force)[i]; });
  out << "      </PointData>\n      <Points>\n";
  VectorArray(out, "position", n, [&](int i) { return st.position_W[i]; });
  out << "      </Points>\n      <Lines>\n"
      << "        <DataArray type=\"Int64\" Name=\"connectivity\" format=\"ascii\">\n         ";
  for (int i = 0; i < n; ++i) out << ' ' << i;
  out << "\n        </DataArray>\n"
      << "        <DataArray type=\"Int64\" Name=\"offsets\" format=\"ascii\">\n          " << n
      << "\n        </DataArray>\n      </Lines>\n    </Piece>\n";
}

bool WriteFile(const std::filesystem::path& path, const std::string& text, std::string* error) {
  std::ofstream f(path);
  f << text;
  f.close();
  if (!f) {
    if (error) *error = path.string() + ": cannot write";
    return false;
  }
  return true;
}

/// Frames `stem`_NNNNNN.vtp numbered `count` and beyond, left by an earlier, longer run into the
/// same directory: ParaView groups every file of the pattern, so they would join this series.
/// Only exact names of the pattern are removed.
void RemoveStaleFrames(const std::string& directory, const std::string& stem, std::size_t count) {
  namespace fs = std::filesystem;
  std::error_code ec;
  std::vector<fs::path> stale;  // removed after the listing, not during it
  for (fs::directory_iterator it(directory, ec), end; !ec && it != end; it.increment(ec)) {
    const std::string name = it->path().filename().string();
    if (name.size() != stem.size() + 11 || name.compare(0, stem.size(), stem) != 0 ||
        name[stem.size()] != '_' || name.compare(name.size() - 4, 4, ".vtp") != 0)
      continue;
    const std::string digits = name.substr(stem.size() + 1, 6);
    if (!std::all_of(digits.begin(), digits.end(), [](char c) { return c >= '0' && c <= '9'; }))
      continue;
    if (std::stoul(digits) >= count) stale.push_back(it->path());
  }
  for (const fs::path& file : stale) fs::remove(file, ec);
}

/// The rigid bodies of a frame as vertices: their origins, with `body` (the index), their axes
/// d1, d2, d3 (the columns of R_WB) and their velocity.
void BodiesPiece(std::ostream& out, const VtkFrame& frame) {
  const int n = static_cast<int>(frame.bodies.size());
  out << "    <Piece NumberOfPoints=\"" << n
      << "\" NumberOfVerts=\"" << n << "\" NumberOfLines=\"0\" NumberOfStrips=\"0\" "
         "NumberOfPolys=\"0\">\n      <PointData>\n";
  out << "        <DataArray type=\"Int32\" Name=\"body\" format=\"ascii\">\n         ";
  for (int i = 0; i < n; ++i) out << ' ' << i;
  out << "\n        </DataArray>\n";
  for (int j = 0; j < 3; ++j) {
    const char* names[] = {"d1", "d2", "d3"};
    VectorArray(out, names[j], n, [&](int i) { return Vec3(frame.bodies[i].R.col(j)); });
  }
  VectorArray(out, "velocity", n, [&](int i) {
    return i < static_cast<int>(frame.body_velocity_W.size()) ? frame.body_velocity_W[i]
                                                              : Vec3::Zero();
  });
  out << "      </PointData>\n      <Points>\n";
  VectorArray(out, "position", n, [&](int i) { return frame.bodies[i].p; });
  out << "      </Points>\n      <Verts>\n"
      << "        <DataArray type=\"Int64\" Name=\"connectivity\" format=\"ascii\">\n         ";
  for (int i = 0; i < n; ++i) out << ' ' << i;
  out << "\n        </DataArray>\n"
      << "        <DataArray type=\"Int64\" Name=\"offsets\" format=\"ascii\">\n         ";
  for (int i = 1; i <= n; ++i) out << ' ' << i;
  out << "\n        </DataArray>\n      </Verts>\n    </Piece>\n";
}

/// Writes `directory`/`stem`_NNNNNN.vtp for frames k = 0 … count − 1, each holding the pieces
/// `pieces(k, out)` writes, and `stem`.pvd listing them at times `t(k)`.
template <typename Time, typename Pieces>
bool WriteSeries(const std::string& directory, const std::string& stem, std::size_t count,
                 const Time& t, const Pieces& pieces, std::string* error) {
  namespace fs = std::filesystem;
  std::ostringstream pvd;
  pvd << std::setprecision(17);
  pvd << "<?xml version=\"1.0\"?>\n"
      << "<VTKFile type=\"Collection\" version=\"0.1\" byte_order=\"LittleEndian\">\n"
      << "  <Collection>\n";
  for (std::size_t k = 0; k < count; ++k) {
    char name[64];
    std::snprintf(name, sizeof name, "_%06zu.vtp", k);
    const std::string file = stem + name;
    std::ostringstream vtp;
    vtp << std::setprecision(17);
    vtp << "<?xml version=\"1.0\"?>\n"
        << "<VTKFile type=\"PolyData\" version=\"0.1\" byte_order=\"LittleEndian\">\n"
        << "  <PolyData>\n";
    pieces(k, vtp);
    vtp << "  </PolyData>\n</VTKFile>\n";
    if (!WriteFile(fs::path(directory) / file, vtp.str(), error)) return false;
    pvd << "    <DataSet timestep=\"" << t(k) << "\" group=\"\" part=\"0\" file=\"" << file
        << "\"/>\n";
  }
  pvd << "  </Collection>\n</VTKFile>\n";
  RemoveStaleFrames(directory, stem, count);
  return WriteFile(fs::path(directory) / (stem + ".pvd"), pvd.str(), error);
}

}  // namespace

bool WriteVtkSeries(const std::string& directory, const std::string& stem,
                    const std::vector<VtkFrame>& frames,
                    const std::vector<std::vector<double>>& radius, std::string* error) {
  std::error_code ec;
  std::filesystem::create_directories(directory, ec);
  if (ec) {
    if (error) *error = directory + ": cannot create the directory (" + ec.message() + ")";
    return false;
  }
  auto t = [&](std::size_t k) { return frames[k].t; };
  auto rods = [&](std::size_t k, std::ostream& vtp) {
    const VtkFrame& frame = frames[k];
    for (std::size_t r = 0; r < frame.rods.size(); ++r)
      Piece(vtp, static_cast<int>(r), frame.rods[r],
            r < frame.radius.size() ? frame.radius[r]
            : r < radius.size()     ? radius[r]
                                    : std::vector<double>{},
            r < frame.contact_force.size() ? &frame.contact_force[r] : nullptr);
  };
  if (!WriteSeries(directory, stem, frames.size(), t, rods, error)) return false;
  if (frames.empty() || frames.front().bodies.empty()) return true;
  auto bodies = [&](std::size_t k, std::ostream& vtp) { BodiesPiece(vtp, frames[k]); };
  return WriteSeries(directory, stem + "_bodies", frames.size(), t, bodies, error);
}

}  // namespace cosserat::io
