// Contexts on different threads render at the same time, each with the bytes it gives alone.
#include <doctest/doctest.h>

#include <atomic>
#include <thread>
#include <vector>

#include "osmesa_test_scene.h"

TEST_CASE("8 threads rendering 8 contexts at once give the serial bytes") {
  constexpr int kThreads = 8, kWidth = 150, kHeight = 110;
  std::vector<std::vector<uint8_t>> serial;
  for (int i = 0; i < kThreads; ++i) serial.push_back(osmesa_test::renderRGBA(kWidth, kHeight, i));

  std::vector<int> failures;
  const auto parallel = osmesa_test::renderOnThreads(
      kThreads, kWidth, kHeight, [] { return OSMesaCreateContextExt(OSMESA_RGBA, 24, 8, 0, nullptr); },
      [](int i) {
        for (int frame = 0; frame < 4; ++frame) osmesa_test::drawScene(i);  // several frames overlap
      },
      failures);
  for (int i = 0; i < kThreads; ++i) {
    CAPTURE(i);
    CHECK(failures[i] == 0);
    CHECK(parallel[i] == serial[i]);
  }
  // The pictures differ between threads: each thread drew its own.
  CHECK(serial[0] != serial[1]);
}

TEST_CASE("a context is current on one thread at most") {
  std::vector<uint8_t> buffer(16 * 16 * 4), other(16 * 16 * 4);
  OSMesaContext ctx = OSMesaCreateContext(OSMESA_RGBA, nullptr);
  REQUIRE(OSMesaMakeCurrent(ctx, buffer.data(), GL_UNSIGNED_BYTE, 16, 16));
  GLboolean elsewhere = GL_TRUE;
  OSMesaContext seenThere = ctx;
  std::thread([&] {
    elsewhere = OSMesaMakeCurrent(ctx, other.data(), GL_UNSIGNED_BYTE, 16, 16);
    seenThere = OSMesaGetCurrentContext();
  }).join();
  CHECK(elsewhere == GL_FALSE);
  CHECK(seenThere == nullptr);
  CHECK(OSMesaGetCurrentContext() == ctx);
  // Released here, it may be made current there.
  REQUIRE(OSMesaMakeCurrent(nullptr, nullptr, 0, 0, 0));
  std::thread([&] {
    elsewhere = OSMesaMakeCurrent(ctx, other.data(), GL_UNSIGNED_BYTE, 16, 16);
    OSMesaMakeCurrent(nullptr, nullptr, 0, 0, 0);
  }).join();
  CHECK(elsewhere == GL_TRUE);
  OSMesaDestroyContext(ctx);
}
