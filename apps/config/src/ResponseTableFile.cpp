#include "ResponseTableFile.h"

#include <array>
#include <cmath>
#include <string>
#include <utility>

#include "DelayTableFile.h"

namespace tofsim::config {

namespace {
struct Unit {
  const char* name;
  double seconds;
};
constexpr std::array<Unit, 5> kDelayUnits{
    {{"s", 1.0}, {"ms", 1e-3}, {"us", 1e-6}, {"ns", 1e-9}, {"ps", 1e-12}}};
}  // namespace

physics::ResponseKernel parseResponseTable(const ConfigNode& n) {
  DelayTableWords words{"a scattering delay table", "weight",
                        "delays count from the light's arrival at the surface",
                        "a delay kernel is >= 0"};
  double scale = 1.0;
  if (const auto unit = n.optionalChild("delay_unit")) {
    const std::string name = unit->asString();
    const Unit* found = nullptr;
    for (const Unit& u : kDelayUnits) {
      if (name == u.name) found = &u;
    }
    if (!found) unit->fail("must be s, ms, us, ns or ps (got '" + name + "')");
    words.delayUnit = found->name;
    scale = found->seconds;
  }
  DelayRows rows = readDelayTable(n, "file", words);
  physics::ResponseKernel kernel;
  kernel.model = physics::ResponseModel::Table;
  kernel.fraction = 1.0;
  kernel.tableDelay_s.reserve(rows.delays.size());
  for (double d : rows.delays) kernel.tableDelay_s.push_back(d * scale);
  kernel.tableWeight = std::move(rows.values);
  return kernel;
}

}  // namespace tofsim::config
