// SPDX-License-Identifier: AGPL-3.0-or-later
#include "tetskin/vtkio/PvdSeries.h"

#include <vtkXMLDataElement.h>
#include <vtkXMLDataParser.h>

#include <algorithm>
#include <cmath>
#include <iomanip>

#include "XmlText.h"
#include "tetskin/core/Error.h"
#include "tetskin/io/AtomicFile.h"
#include "tetskin/vtkio/VtkErrorCapture.h"

namespace tetskin {

PvdSeries::PvdSeries(std::filesystem::path pvdPath) : path_(std::move(pvdPath)) {}

PvdSeries PvdSeries::read(const std::filesystem::path& pvdPath) {
  const std::string file = pvdPath.string();
  if (!std::filesystem::is_regular_file(pvdPath)) throw Error(file, 0, "cannot open for reading");
  auto parser = vtkSmartPointer<vtkXMLDataParser>::New();
  VtkErrorCapture errors(parser);
  parser->SetFileName(pvdPath.c_str());
  if (!parser->Parse() || !parser->GetRootElement())
    throw Error(file, 0, "is not a readable XML file: " + errors.message("no root element"));
  vtkXMLDataElement* root = parser->GetRootElement();
  const char* type = root->GetAttribute("type");
  vtkXMLDataElement* collection = root->FindNestedElementWithName("Collection");
  if (std::string(root->GetName()) != "VTKFile" || !type || std::string(type) != "Collection" ||
      !collection)
    throw Error(file, 0, "is not a ParaView time series (no VTKFile of type Collection)");
  PvdSeries series(pvdPath);
  for (int i = 0; i < collection->GetNumberOfNestedElements(); ++i) {
    vtkXMLDataElement* dataSet = collection->GetNestedElement(i);
    if (std::string(dataSet->GetName()) != "DataSet") continue;
    const char* name = dataSet->GetAttribute("file");
    double time = 0;
    int part = 0;
    if (!name || !*name || !dataSet->GetScalarAttribute("timestep", time) || !std::isfinite(time))
      throw Error(file, 0, "DataSet " + std::to_string(i) + " has no file or no finite timestep");
    dataSet->GetScalarAttribute("part", part);  // optional
    series.add(time, part, name);
  }
  return series;
}

std::vector<PvdSeries::Entry> PvdSeries::framesOfPart(int part) const {
  std::vector<Entry> frames;
  for (const Entry& entry : entries_)
    if (entry.part == part) frames.push_back(entry);
  if (frames.empty())
    throw Error(path_.string(), 0,
                "has no frames of part " + std::to_string(part) +
                    (part == 0   ? " (the control mesh)"
                     : part == 1 ? " (the surface)"
                                 : ""));
  std::stable_sort(frames.begin(), frames.end(),
                   [](const Entry& x, const Entry& y) { return x.time < y.time; });
  for (Entry& frame : frames) {
    const std::filesystem::path file = path_.parent_path() / frame.file;
    if (!std::filesystem::exists(file))
      throw Error(path_.string(), 0, "names the frame " + frame.file + ", which is not there");
    frame.file = file.string();
  }
  return frames;
}

void PvdSeries::add(double time, int part, const std::string& file) {
  entries_.push_back({time, part, file});
}

void PvdSeries::write() const {
  writeTextAtomically(path_, [&](std::ostream& out) {
    out << "<?xml version=\"1.0\"?>\n"
        << "<VTKFile type=\"Collection\" version=\"0.1\" byte_order=\"LittleEndian\">\n"
        << "  <Collection>\n";
    for (const Entry& e : entries_)
      out << "    <DataSet timestep=\"" << std::setprecision(17) << e.time
          << "\" group=\"\" part=\"" << e.part << "\" file=\"" << detail::xmlEscaped(e.file)
          << "\"/>\n";
    out << "  </Collection>\n</VTKFile>\n";
  });
}

}  // namespace tetskin
