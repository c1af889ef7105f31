#include "tofsim/io/Exr.h"

#include <ImfChannelList.h>
#include <ImfFrameBuffer.h>
#include <ImfHeader.h>
#include <ImfInputFile.h>
#include <ImfOutputFile.h>
#include <ImfStandardAttributes.h>
#include <ImfStdIO.h>
#include <ImfStringVectorAttribute.h>

#include <algorithm>
#include <exception>
#include <set>

#include "tofsim/util/AtomicFile.h"
#include "tofsim/util/Error.h"

namespace tofsim::io {

namespace {

// Header attribute recording the writer's channel order (EXR itself stores
// channels sorted by name).
constexpr const char* kChannelOrderAttr = "tofsimChannelOrder";

Imf::Slice floatSlice(float* base, const Image& image, int channel) {
  const std::size_t xStride = sizeof(float) * static_cast<std::size_t>(image.channels);
  return Imf::Slice(Imf::FLOAT, reinterpret_cast<char*>(base + channel), xStride,
                    xStride * static_cast<std::size_t>(image.width));
}

std::vector<std::string> readOrder(const Imf::Header& header) {
  std::vector<std::string> fileOrder;
  for (auto it = header.channels().begin(); it != header.channels().end(); ++it) {
    fileOrder.emplace_back(it.name());
  }
  if (const auto* attr = header.findTypedAttribute<Imf::StringVectorAttribute>(kChannelOrderAttr)) {
    std::vector<std::string> written = attr->value();
    std::vector<std::string> a = written, b = fileOrder;
    std::sort(a.begin(), a.end());
    std::sort(b.begin(), b.end());
    if (a == b) return written;
  }
  std::vector<std::string> order;
  for (const char* rgba : {"R", "G", "B", "A"}) {
    if (std::find(fileOrder.begin(), fileOrder.end(), rgba) != fileOrder.end())
      order.push_back(rgba);
  }
  for (const std::string& n : fileOrder) {
    if (std::find(order.begin(), order.end(), n) == order.end()) order.push_back(n);
  }
  return order;
}

}  // namespace

void writeExr(const std::filesystem::path& path, const Image& image,
              const std::vector<std::string>& channelNames) {
  const std::string name = path.string();
  TOFSIM_CHECK(image.width > 0 && image.height > 0 && image.channels > 0);
  TOFSIM_CHECK(image.data.size() ==
               static_cast<std::size_t>(image.width) * image.height * image.channels);
  if (channelNames.size() != static_cast<std::size_t>(image.channels)) {
    throw InputError(FileLoc{name}, "",
                     "EXR needs one channel name per channel (got " +
                         std::to_string(channelNames.size()) + " names for " +
                         std::to_string(image.channels) + " channels)");
  }
  const std::set<std::string> unique(channelNames.begin(), channelNames.end());
  if (unique.size() != channelNames.size() || unique.count("")) {
    throw InputError(FileLoc{name}, "", "EXR channel names must be unique and non-empty");
  }

  // Encoded in memory and written by AtomicFile: whole or not at all, and
  // its temporary is opened without following a link (OpenEXR's own file
  // opening would follow one planted at a guessable name).
  std::string bytes;
  try {
    Imf::Header header(image.width, image.height);
    header.compression() = Imf::ZIP_COMPRESSION;
    header.insert(kChannelOrderAttr, Imf::StringVectorAttribute(channelNames));
    Imf::FrameBuffer frame;
    // OpenEXR's API takes non-const pointers but only reads when writing.
    float* base = const_cast<float*>(image.data.data());
    for (int c = 0; c < image.channels; ++c) {
      header.channels().insert(channelNames[c], Imf::Channel(Imf::FLOAT));
      frame.insert(channelNames[c], floatSlice(base, image, c));
    }
    Imf::StdOSStream stream;
    {
      Imf::OutputFile out(stream, header);
      out.setFrameBuffer(frame);
      out.writePixels(image.height);
    }
    bytes = stream.str();
  } catch (const std::exception& e) {
    throw InputError(FileLoc{name}, "", std::string("cannot write EXR: ") + e.what());
  }
  writeFileAtomically(path, bytes);
}

Image readExr(const std::filesystem::path& path, std::vector<std::string>* channelNames) {
  const std::string name = path.string();
  std::error_code ec;
  if (!std::filesystem::exists(path, ec)) throw InputError(FileLoc{name}, "", "EXR file not found");
  try {
    Imf::InputFile in(path.c_str());
    const Imath::Box2i window = in.header().dataWindow();
    const std::vector<std::string> order = readOrder(in.header());
    Image image(window.max.x - window.min.x + 1, window.max.y - window.min.y + 1,
                static_cast<int32_t>(order.size()));
    // The slice base is offset so that pixel (min.x, min.y) lands at index 0.
    float* origin =
        image.data.data() -
        (static_cast<std::ptrdiff_t>(window.min.y) * image.width + window.min.x) * image.channels;
    Imf::FrameBuffer frame;
    for (int c = 0; c < image.channels; ++c) {
      frame.insert(order[c], floatSlice(origin, image, c));
    }
    in.setFrameBuffer(frame);
    in.readPixels(window.min.y, window.max.y);
    if (channelNames) *channelNames = order;
    return image;
  } catch (const InputError&) {
    throw;
  } catch (const std::exception& e) {
    throw InputError(FileLoc{name}, "", std::string("cannot read EXR: ") + e.what());
  }
}

}  // namespace tofsim::io
