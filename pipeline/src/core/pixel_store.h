// glPixelStore parameters (spec 3.6.1 and 4.3.2; table 6.13): how pixel data is laid out in
// client memory, for glReadPixels (pack) and for texture images (unpack).
#pragma once

namespace glass::gl {

struct PixelPacking {
  bool swapBytes = false;
  bool lsbFirst = false;
  int rowLength = 0;    // 0: rows are as long as the image
  int skipRows = 0;
  int skipPixels = 0;
  int alignment = 4;    // 1, 2, 4 or 8
  int imageHeight = 0;
  int skipImages = 0;
};

struct PixelStoreState {
  PixelPacking pack;
  PixelPacking unpack;
};

// Bytes from the start of one row to the next for an image `width` pixels wide, of pixels
// `pixelBytes` bytes, with components `componentBytes` bytes each (spec 3.6.1, equation 3.1).
long long rowStrideBytes(const PixelPacking& packing, int width, int pixelBytes, int componentBytes);

}  // namespace glass::gl
