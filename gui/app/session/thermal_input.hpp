// Thermal loads as the dialogs ask for them: *INITIAL CONDITIONS, TYPE=TEMPERATURE and a step's
// *TEMPERATURE, each a value on every node of a node set (the material's *EXPANSION is in the
// material dialog, validation.hpp). A node given again takes the new value.
#pragma once

#include <memory>
#include <string>

#include "session/commands.hpp"
#include "styk/core/model.hpp"

namespace styk::gui {

struct TemperatureInput {
  std::string nset;
  double value = 0.0;
  int step = -1;  // -1: the initial temperature; otherwise *TEMPERATURE of steps[step]
};
std::unique_ptr<Command> temperature_command(const Model& model, const TemperatureInput& input);

}  // namespace styk::gui
