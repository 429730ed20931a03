#include "contact/SurfaceFile.hpp"

#include <algorithm>
#include <cctype>

#include "contact/ObjReader.hpp"
#include "contact/StlReader.hpp"
#include "contact/SurfaceError.hpp"

namespace glossa::contact {

TriangleSurface readSurface(const std::string &path, double scale) {
  const std::size_t dot = path.find_last_of('.');
  const std::size_t slash = path.find_last_of('/');
  std::string extension =
      dot == std::string::npos || (slash != std::string::npos && dot < slash) ? "" : path.substr(dot);
  std::transform(extension.begin(), extension.end(), extension.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  if (extension == ".obj") return readObj(path, scale);
  if (extension == ".stl") return readStl(path, scale);
  throw SurfaceError(path + ": cannot tell the surface format from the extension '" + extension +
                     "' (allowed: .obj, .stl)");
}

}  // namespace glossa::contact
