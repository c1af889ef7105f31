// The MP4 encoder as a module of its own, loaded (dlopen) only by a run that
// writes a video (VideoModule.h): OpenCV's videoio pulls in FFmpeg and
// GStreamer, some 240 shared libraries whose loading cost every tofsim
// process 0.1 s before it did anything. A C interface, so that the loader
// needs no C++ symbols.
#include <opencv2/core.hpp>
#include <opencv2/videoio.hpp>

extern "C" {

// An open MP4 writer (fourcc mp4v) of width x height BGR frames, or null.
__attribute__((visibility("default"))) void* tofsim_video_open(const char* path, double fps,
                                                               int width, int height) {
  auto* writer = new cv::VideoWriter;
  writer->open(path, cv::VideoWriter::fourcc('m', 'p', '4', 'v'), fps, cv::Size(width, height),
               true);
  if (!writer->isOpened()) {
    delete writer;
    return nullptr;
  }
  return writer;
}

// Appends one frame: height rows of width BGR pixels, `stride` bytes apart.
__attribute__((visibility("default"))) void tofsim_video_write(void* writer,
                                                               const unsigned char* bgr, int width,
                                                               int height, unsigned long stride) {
  const cv::Mat frame(height, width, CV_8UC3, const_cast<unsigned char*>(bgr), stride);
  static_cast<cv::VideoWriter*>(writer)->write(frame);
}

// Finishes the file and frees the writer.
__attribute__((visibility("default"))) void tofsim_video_close(void* writer) {
  auto* w = static_cast<cv::VideoWriter*>(writer);
  w->release();
  delete w;
}
}
