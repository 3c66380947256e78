// How many threads glass works on: GLASS_THREADS, a whole number from 1 to 256, when set;
// otherwise as many as the machine has hardware threads. The count changes the speed, never the
// bytes: the tiled rasterizer (tiled_rasterizer.h) and the attempts of the homework 3 fit
// (glass/course/ifs3d_fit.h) give the same results on any number of threads.
#pragma once

namespace glass::raster {

int configuredThreadCount();

}  // namespace glass::raster
