// The pinned scene's hash as the fuzz build's compiler (clang) computes it: CI builds this with
// the harnesses (`./run fuzz`) and fails when it differs from the value g++ gives
// (Determinism2D.the_reference_scene_hash_is_pinned): the same inputs give the same bits with
// either compiler, at either SIMD width.
#include "../rigid2d/mixed_scene.hpp"

#include <cstdio>

int main() {
  using namespace impetus::rigid2d;
  int failures = 0;
  for (const SimdLevel simd : {SimdLevel::baseline, SimdLevel::widest}) {
    const std::uint64_t hash = test::runMixedScene(nullptr, simd);
    const bool same = hash == test::pinnedMixedSceneHash;
    std::printf("pinned scene, %s: 0x%016llx %s\n", simd == SimdLevel::baseline ? "SSE2" : "widest",
                static_cast<unsigned long long>(hash), same ? "(pinned)" : "DIFFERS from the pinned value");
    failures += same ? 0 : 1;
  }
  return failures == 0 ? 0 : 1;
}
