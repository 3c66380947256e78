// The rounded triangles of a .wings model, kept for the radii drawn last (rounded_parts_cache.h).
#include "load/rounded_parts_cache.h"

#include "load/wings_model.h"

#include <algorithm>

namespace glass::scene {

std::shared_ptr<const std::vector<ModelPart>> RoundedPartsCache::partsFor(const RoundableModel &model, double radius) {
  // One rounding at a time: threads asking for the same radius wait for it instead of making it
  // twice.
  const std::lock_guard<std::mutex> lock(mutex_);
  const auto kept = std::find_if(entries_.begin(), entries_.end(), [&](const Entry &e) { return e.radius == radius; });
  if (kept != entries_.end()) {
    Entry entry = *kept;
    entries_.erase(kept);
    entries_.push_back(entry);
    return entry.parts;
  }
  auto parts = std::make_shared<const std::vector<ModelPart>>(roundedWingsParts(model, radius));
  ++roundings_;
  if (entries_.size() == kKeptRadii) entries_.erase(entries_.begin());
  entries_.push_back({radius, parts});
  return parts;
}

std::size_t RoundedPartsCache::roundings() const {
  const std::lock_guard<std::mutex> lock(mutex_);
  return roundings_;
}

} // namespace glass::scene
