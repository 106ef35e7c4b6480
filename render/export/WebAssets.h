// WebAssets.h -- the files a web page is made of, compiled into the library (render/CMakeLists.txt writes
// them into a generated source at configure time): three.js and its OrbitControls (Debian's libjs-three,
// revision 111, pinned there; MIT licence, its notice kept in the file) and rollviz's own page template and
// viewer (render/export/web/).
#pragma once
#include <string_view>

namespace rv {

enum class WebAsset { ThreeJs, OrbitControls, PageHtml, PageJs };

/// The file's text.
std::string_view webAsset(WebAsset asset);

/// The three.js revision embedded ("111").
std::string_view threeJsRevision();

} // namespace rv
