// SPDX-License-Identifier: AGPL-3.0-or-later
#include "tetskin/io/NodeList.h"

#include <algorithm>
#include <string>

#include "TextLines.h"
#include "tetskin/core/Error.h"

namespace tetskin {

std::vector<int> readNodeList(const std::filesystem::path& path, Index nodeCount) {
  const std::string content = detail::readWholeFile(path);
  detail::TextLines lines(content, path.string());
  std::vector<int> nodes;
  while (lines.next())
    for (std::string_view token : lines.tokens()) {
      const long long node = lines.toInteger(token, "node number");
      if (node < 0 || node >= nodeCount)
        lines.fail("node " + std::to_string(node) + " does not exist (the level has " +
                   std::to_string(nodeCount) + " nodes, numbered from 0)");
      nodes.push_back(static_cast<int>(node));
    }
  if (nodes.empty()) throw Error(path.string(), 0, "no node numbers in the file");
  std::sort(nodes.begin(), nodes.end());
  nodes.erase(std::unique(nodes.begin(), nodes.end()), nodes.end());
  return nodes;
}

}  // namespace tetskin
