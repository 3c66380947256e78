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

  std::vector<std::vector<uint8_t>> parallel(kThreads);
  std::vector<int> failures(kThreads, 0);
  std::atomic<int> ready{0};
  std::vector<std::thread> threads;
  for (int i = 0; i < kThreads; ++i) {
    threads.emplace_back([&, i] {
      OSMesaContext ctx = OSMesaCreateContextExt(OSMESA_RGBA, 24, 8, 0, nullptr);
      parallel[i].assign(static_cast<size_t>(kWidth) * kHeight * 4, 0);
      if (!ctx || !OSMesaMakeCurrent(ctx, parallel[i].data(), GL_UNSIGNED_BYTE, kWidth, kHeight)) {
        failures[i] = 1;
        ++ready;
        return;
      }
      // Start drawing together, and draw several frames, so that the threads overlap.
      ++ready;
      while (ready.load() < kThreads) std::this_thread::yield();
      for (int frame = 0; frame < 4; ++frame) osmesa_test::drawScene(i);
      if (OSMesaGetCurrentContext() != ctx || glGetError() != GL_NO_ERROR) failures[i] = 1;
      OSMesaDestroyContext(ctx);
    });
  }
  for (std::thread& thread : threads) thread.join();
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
