#include "session/contact_input.hpp"

#include <utility>

#include "session/input_checks.hpp"

namespace styk::gui {
namespace {

struct Checked {
  SurfaceInteraction interaction;
  ContactPair pair;
};

Checked check_contact(const Model& model, const ContactInput& in, int replacing) {
  const Surface& slave = existing_surface(model, in.slave);
  const Surface& master = existing_surface(model, in.master);
  if (slave.name == master.name)
    refuse("slave and master are the same surface " + slave.name +
           "; self-contact is not supported");
  if (master.kind != Surface::Kind::ElementFaces)
    refuse("the master " + master.name + " must be a surface of element faces");
  if (in.type != ContactPair::Type::NodeToSurface && slave.kind != Surface::Kind::ElementFaces)
    refuse(std::string(in.type == ContactPair::Type::Mortar ? "mortar" : "surface to surface") +
           " needs element faces on the slave " + slave.name + " too");
  check_name(in.interaction, "the interaction");
  const std::string name = to_upper(in.interaction);
  const std::string own =
      replacing >= 0 ? model.contact_pairs.at(replacing).interaction : std::string();
  if (model.surface_interactions.count(name) && name != own)
    refuse("interaction " + name + " exists already; choose another name");
  for (std::size_t i = 0; i < model.contact_pairs.size(); ++i)
    if (static_cast<int>(i) != replacing && model.contact_pairs[i].slave == slave.name &&
        model.contact_pairs[i].master == master.name)
      refuse("a contact pair " + slave.name + " / " + master.name + " exists already");
  Checked out;
  out.interaction.name = name;
  // The form edits friction only: an edited pair keeps its interaction's *SURFACE BEHAVIOR law.
  if (const auto kept = model.surface_interactions.find(own);
      !own.empty() && kept != model.surface_interactions.end())
    out.interaction.behavior = kept->second.behavior;
  const std::string kind = to_upper(in.friction);
  check_finite(in.mu, "friction coefficient");
  check_finite(in.mu2, "friction coefficient mu2");
  if (kind == "ISOTROPIC" || kind == "ANISOTROPIC") {
    if (in.mu < 0) refuse("friction coefficient must be >= 0, not " + std::to_string(in.mu));
    Friction f;
    f.mu = in.mu;
    if (kind == "ANISOTROPIC") {
      if (in.mu2 < 0) refuse("friction coefficient mu2 must be >= 0");
      if (in.orientation.empty())
        refuse("anisotropic friction needs an orientation (its axes 1, 2)");
      if (!model.orientations.count(to_upper(in.orientation)))
        refuse("no orientation " + to_upper(in.orientation) + " in the model");
      f.kind = Friction::Kind::Anisotropic;
      f.mu2 = in.mu2;
      f.orientation = to_upper(in.orientation);
    }
    if (kind == "ANISOTROPIC" || in.mu > 0) out.interaction.friction = f;
  } else if (kind == "ROUGH") {
    Friction f;
    f.kind = Friction::Kind::Rough;
    out.interaction.friction = f;
  } else if (kind != "FRICTIONLESS") {
    refuse("friction must be frictionless, isotropic, anisotropic or rough, not " + in.friction);
  }
  out.pair.type = in.type;
  out.pair.slave = slave.name;
  out.pair.master = master.name;
  out.pair.interaction = name;
  if (in.has_clearance) {
    check_finite(in.clearance, "clearance");
    out.pair.clearance = in.clearance;
  }
  return out;
}

}  // namespace

std::unique_ptr<Command> contact_command(const Model& model, const ContactInput& in,
                                         int replacing) {
  Checked c = check_contact(model, in, replacing);
  const std::string text = "Contact " + c.pair.slave + " / " + c.pair.master;
  if (replacing < 0) {
    return make_model_edit(
        "Add " + text,
        [c](Model& m) {
          m.surface_interactions[c.interaction.name] = c.interaction;
          m.contact_pairs.push_back(c.pair);
        },
        [name = c.interaction.name](Model& m) {
          m.contact_pairs.pop_back();
          m.surface_interactions.erase(name);
        });
  }
  const ContactPair old_pair = model.contact_pairs.at(replacing);
  const SurfaceInteraction old_interaction = model.surface_interactions.at(old_pair.interaction);
  // An interaction other pairs use too stays (under its name, the edit changes it for them).
  bool shared = false;
  for (std::size_t i = 0; i < model.contact_pairs.size(); ++i)
    shared = shared || (static_cast<int>(i) != replacing &&
                        model.contact_pairs[i].interaction == old_pair.interaction);
  return make_model_edit(
      "Edit " + text,
      [c, replacing, shared, old_name = old_pair.interaction](Model& m) {
        if (!shared) m.surface_interactions.erase(old_name);
        m.surface_interactions[c.interaction.name] = c.interaction;
        m.contact_pairs[replacing] = c.pair;
      },
      [c, replacing, old_pair, old_interaction](Model& m) {
        if (c.interaction.name != old_interaction.name)
          m.surface_interactions.erase(c.interaction.name);
        m.surface_interactions[old_interaction.name] = old_interaction;
        m.contact_pairs[replacing] = old_pair;
      });
}

ContactInput contact_input_of(const Model& model, int pair) {
  const ContactPair& p = model.contact_pairs.at(pair);
  ContactInput in;
  in.slave = p.slave;
  in.master = p.master;
  in.interaction = p.interaction;
  in.type = p.type;
  in.has_clearance = p.clearance.has_value();
  in.clearance = p.clearance.value_or(0.0);
  in.friction = "frictionless";
  in.mu = 0.0;
  const auto it = model.surface_interactions.find(p.interaction);
  if (it != model.surface_interactions.end() && it->second.friction) {
    const Friction& f = *it->second.friction;
    in.friction = f.kind == Friction::Kind::Rough         ? "rough"
                  : f.kind == Friction::Kind::Anisotropic ? "anisotropic"
                                                          : "isotropic";
    in.mu = f.mu;
    in.mu2 = f.mu2;
    in.orientation = f.orientation;
  }
  return in;
}

}  // namespace styk::gui
