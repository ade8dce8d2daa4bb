// Dropping pose ops (search/proposals.h).
#include "search/proposals.h"

namespace opgraph {

std::vector<Round> ProposePoseDrops(const Layout& best) {
  Round round;
  round.finishing = true;
  const bool rotated = !best.rotate.is_null(), translated = !best.translate.is_null();
  if (rotated) {
    round.alternatives.push_back([](Layout* l) -> std::string {
      l->rotate = nullptr;
      return "-GlobalAffineRotate";
    });
  }
  if (translated) {
    round.alternatives.push_back([](Layout* l) -> std::string {
      l->translate = nullptr;
      return "-GlobalAffineTranslate";
    });
  }
  if (rotated && translated) {
    round.alternatives.push_back([](Layout* l) -> std::string {
      l->rotate = nullptr, l->translate = nullptr;
      return "-GlobalAffineRotate -GlobalAffineTranslate";
    });
  }
  if (round.alternatives.empty()) return {};
  return {round};
}

}  // namespace opgraph
