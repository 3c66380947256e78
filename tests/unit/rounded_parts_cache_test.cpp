// The rounded parts of a .wings model are made once per radius and handed out again
// (scene/src/load/rounded_parts_cache.h): what is handed out equals a new rounding, each radius is
// rounded once while it stays among the kept ones, and a radius that cannot be rounded is refused
// every time with nothing kept.
#include <doctest/doctest.h>

#include <string>
#include <vector>

#include "glass/geometry/edge_rounding.h"
#include "load/rounded_parts_cache.h"
#include "load/wings_model.h"

namespace {

bool sameParts(const std::vector<glass::scene::ModelPart> &a, const std::vector<glass::scene::ModelPart> &b) {
  if (a.size() != b.size()) return false;
  for (std::size_t i = 0; i < a.size(); ++i) {
    if (a[i].material != b[i].material || a[i].positions != b[i].positions || a[i].normals != b[i].normals ||
        a[i].texcoords != b[i].texcoords)
      return false;
  }
  return true;
}

}  // namespace

TEST_CASE("rounded_parts_cache_keeps_each_radius") {
  glass::scene::Model model;
  std::string reason;
  REQUIRE_MESSAGE(glass::scene::loadWingsModel(GLASS_SOURCE_DIR "/scenes/models/block.wings", model, reason), reason);
  REQUIRE(model.roundable != nullptr);
  const glass::scene::RoundableModel &roundable = *model.roundable;
  glass::scene::RoundedPartsCache cache;

  const auto first = cache.partsFor(roundable, 0.2);
  CHECK(sameParts(*first, glass::scene::roundedWingsParts(roundable, 0.2)));
  CHECK(!first->empty());
  CHECK(cache.partsFor(roundable, 0.2) == first);  // handed out again, not made again
  CHECK(cache.roundings() == 1);

  // Other radii are made and kept; the least recently used goes when a fifth comes.
  for (const double r : {0.05, 0.1, 0.15}) cache.partsFor(roundable, r);
  CHECK(cache.roundings() == 4);
  CHECK(cache.partsFor(roundable, 0.2) == first);  // 0.2 is now the most recently used
  cache.partsFor(roundable, 0.25);                 // 0.05 goes
  CHECK(cache.roundings() == 5);
  cache.partsFor(roundable, 0.1);
  CHECK(cache.roundings() == 5);
  const auto again = cache.partsFor(roundable, 0.05);
  CHECK(cache.roundings() == 6);
  CHECK(sameParts(*again, glass::scene::roundedWingsParts(roundable, 0.05)));

  // A radius too large is refused each time, and nothing is kept for it.
  CHECK_THROWS_AS(cache.partsFor(roundable, 1000.0), glass::geometry::RoundingError);
  CHECK_THROWS_AS(cache.partsFor(roundable, 1000.0), glass::geometry::RoundingError);
  CHECK(cache.roundings() == 6);
}
