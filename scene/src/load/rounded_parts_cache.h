// The rounded triangles of a .wings model, kept for the radii drawn last. Rounding and
// tessellating a model is most of the work of a frame that draws it (the room scene draws its
// object four times a frame, once lit and three times as a shadow, and the parser rounds it once
// to check the radius), while the radius changes only when the user presses R or an animation
// moves it. The parts for a radius are the same whenever they are made, so a frame drawn from
// kept parts is the frame drawn from new ones, byte for byte.
#pragma once

#include "glass/scene/program.h"

#include <cstddef>
#include <memory>
#include <mutex>
#include <vector>

namespace glass::scene {

struct RoundableModel;

class RoundedPartsCache {
 public:
  // How many radii are kept: an animation of the radius makes a new one every frame, and the
  // oldest goes.
  static constexpr std::size_t kKeptRadii = 4;

  // roundedWingsParts(model, radius) (wings_model.h), made on the first call for the radius and
  // kept. Throws what it throws, keeping nothing. Safe to call from several threads.
  std::shared_ptr<const std::vector<ModelPart>> partsFor(const RoundableModel &model, double radius);

  // How many times partsFor has made parts instead of handing out kept ones.
  std::size_t roundings() const;

 private:
  struct Entry {
    double radius;
    std::shared_ptr<const std::vector<ModelPart>> parts;
  };
  mutable std::mutex mutex_;
  std::vector<Entry> entries_;  // the most recently used last
  std::size_t roundings_ = 0;
};

} // namespace glass::scene
