// arnoldweb explorer: the page's static files (explorer/web/), embedded at build time. The
// server answers only these names; view writes them beside view.html.
#pragma once

#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace arnoldweb::explorer {

// The file `name` ("app.js"), or nothing for any other name.
std::optional<std::string_view> web_file(const std::string& name);
std::vector<std::string> web_file_names();
// Its Content-Type, from its extension.
std::string content_type(const std::string& name);
// index.html with `scripts` (script elements) put where the page takes the runs' data scripts.
std::string page_with_scripts(const std::string& scripts);

}  // namespace arnoldweb::explorer
