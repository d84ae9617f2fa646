#include "Output/PvdCollection.h"

#include <iomanip>
#include <sstream>

#include "Output/VtkFiles.h"

namespace soak {

void PvdCollection::add(double time, const std::string& file) {
  entries_.emplace_back(time, file);
  write();
}

void PvdCollection::restore(std::vector<Entry> entries) {
  entries_ = std::move(entries);
  write();
}

void PvdCollection::write() const {
  std::ostringstream o;
  o << "<?xml version=\"1.0\"?>\n"
    << "<VTKFile type=\"Collection\" version=\"0.1\" byte_order=\"LittleEndian\">\n  <Collection>\n";
  for (const auto& e : entries_)
    o << "    <DataSet timestep=\"" << std::setprecision(10) << e.first << "\" group=\"\" part=\"0\" file=\""
      << e.second << "\"/>\n";
  o << "  </Collection>\n</VTKFile>\n";
  writeFileAtomically(path_, o.str(), /*durable=*/false);
}

}  // namespace soak
