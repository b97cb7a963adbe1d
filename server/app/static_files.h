#pragma once

#include "strahler/http/http_types.h"

#include <string>
#include <vector>

namespace strahler::app {

/// A file of the built viewer under `webRoot` (web_root.h), by decoded path segments, with
/// its MIME type (route "static"); 404 when `webRoot` is "", the file is missing, or its type
/// is not one the viewer uses.
http::Response staticFile(const std::string& webRoot, const std::vector<std::string>& segments);

/// The page at "/" (route "viewer"): the viewer's index.html, or, without a viewer, a page
/// linking each of `worldIds`' documents and a tile.
http::Response indexPage(const std::string& webRoot, const std::vector<std::string>& worldIds);

} // namespace strahler::app
