#include "AccessorReader.h"

#include <algorithm>
#include <cstring>
#include <limits>

#include "tofsim/util/Error.h"

namespace tofsim::scene::detail {

namespace {

std::size_t componentSize(int type) {
  switch (type) {
    case kByte:
    case kUnsignedByte: return 1;
    case kShort:
    case kUnsignedShort: return 2;
    case kUnsignedInt:
    case kFloat: return 4;
    default: return 0;
  }
}

template <typename T>
T load(const unsigned char* p) {
  T v;
  std::memcpy(&v, p, sizeof(T));
  return v;
}

double decode(const unsigned char* p, int type, bool normalized) {
  switch (type) {
    case kByte: {
      const double v = load<int8_t>(p);
      return normalized ? std::max(v / 127.0, -1.0) : v;
    }
    case kUnsignedByte: return normalized ? load<uint8_t>(p) / 255.0 : load<uint8_t>(p);
    case kShort: {
      const double v = load<int16_t>(p);
      return normalized ? std::max(v / 32767.0, -1.0) : v;
    }
    case kUnsignedShort: return normalized ? load<uint16_t>(p) / 65535.0 : load<uint16_t>(p);
    case kUnsignedInt: return normalized ? load<uint32_t>(p) / 4294967295.0 : load<uint32_t>(p);
    default: return load<float>(p);
  }
}

class Reader {
 public:
  Reader(const GltfDocument& doc, int index, const std::string& what)
      : doc_(doc), where_("accessor[" + std::to_string(index) + "] (" + what + ")") {
    if (index < 0 || index >= static_cast<int>(doc.accessors.size())) {
      fail("does not exist (" + std::to_string(doc.accessors.size()) + " accessors)");
    }
  }

  [[noreturn]] void fail(const std::string& message) const {
    throw InputError(FileLoc{doc_.file}, where_, message);
  }

  /// Bytes [offset, offset + (count-1)*stride + elementBytes) of a view,
  /// checked against the view and the view against its buffer.
  const unsigned char* span(int view, std::size_t offset, std::size_t count, std::size_t stride,
                            std::size_t elementBytes) const {
    if (view < 0 || view >= static_cast<int>(doc_.bufferViews.size())) {
      fail("bufferView " + std::to_string(view) + " does not exist");
    }
    const BufferView& v = doc_.bufferViews[view];
    if (v.buffer < 0 || v.buffer >= static_cast<int>(doc_.buffers.size())) {
      fail("bufferView " + std::to_string(view) + " names a missing buffer");
    }
    const auto& buffer = doc_.buffers[v.buffer];
    const std::string bufferName = doc_.bufferNames[v.buffer];
    if (v.byteOffset > buffer.size() || v.byteLength > buffer.size() - v.byteOffset) {
      fail("bufferView " + std::to_string(view) + " runs past the end of " + bufferName + " (" +
           std::to_string(buffer.size()) + " bytes)");
    }
    if (count == 0) return buffer.data();
    const std::size_t limit = std::numeric_limits<std::size_t>::max() / 2;
    if (count > limit / std::max<std::size_t>(stride, 1) || offset > limit) fail("is too large");
    const std::size_t needed = offset + (count - 1) * stride + elementBytes;
    if (needed > v.byteLength) {
      fail("needs " + std::to_string(needed) + " bytes of bufferView " + std::to_string(view) +
           " in " + bufferName + ", which has " + std::to_string(v.byteLength));
    }
    return buffer.data() + v.byteOffset + offset;
  }

 private:
  const GltfDocument& doc_;
  std::string where_;
};

}  // namespace

std::vector<double> readAccessor(const GltfDocument& doc, int index, const std::string& what) {
  const Reader reader(doc, index, what);
  const Accessor& a = doc.accessors[index];
  const std::size_t compBytes = componentSize(a.componentType);
  if (compBytes == 0 || a.components <= 0) reader.fail("unsupported component type or type");
  const std::size_t n = static_cast<std::size_t>(a.components);
  const std::size_t elementBytes = compBytes * n;

  std::vector<double> out;
  if (a.bufferView >= 0) {
    const bool viewExists = a.bufferView < static_cast<int>(doc.bufferViews.size());
    const std::size_t viewStride = viewExists ? doc.bufferViews[a.bufferView].byteStride : 0;
    const std::size_t stride = viewStride ? viewStride : elementBytes;
    const unsigned char* base = reader.span(a.bufferView, a.byteOffset, a.count, stride, elementBytes);
    out.resize(a.count * n);
    for (std::size_t i = 0; i < a.count; ++i) {
      for (std::size_t c = 0; c < n; ++c) {
        out[i * n + c] = decode(base + i * stride + c * compBytes, a.componentType, a.normalized);
      }
    }
  } else {
    // No bufferView: zeros, to be replaced by sparse values. Bound the
    // allocation by what a sparse-only accessor can sensibly describe.
    if (!a.sparse) reader.fail("has neither a bufferView nor sparse data");
    // 2^24 values (128 MiB of doubles): a MAT4 accessor of 2^28 elements
    // would have asked for 34 GB here (found by fuzzing).
    if (a.count > (std::size_t{1} << 24) / n) reader.fail("is too large for a sparse-only accessor");
    out.assign(a.count * n, 0.0);
  }

  if (a.sparse) {
    const Sparse& s = *a.sparse;
    const std::size_t idxBytes = componentSize(s.indicesComponentType);
    if (idxBytes == 0 || s.indicesComponentType == kByte || s.indicesComponentType == kShort ||
        s.indicesComponentType == kFloat) {
      reader.fail("sparse indices have an invalid component type");
    }
    if (s.count > a.count) reader.fail("has more sparse values than elements");
    const unsigned char* idx = reader.span(s.indicesView, s.indicesOffset, s.count, idxBytes, idxBytes);
    const unsigned char* val = reader.span(s.valuesView, s.valuesOffset, s.count, elementBytes, elementBytes);
    for (std::size_t k = 0; k < s.count; ++k) {
      const double target = decode(idx + k * idxBytes, s.indicesComponentType, false);
      if (target >= static_cast<double>(a.count)) {
        reader.fail("sparse index " + std::to_string(static_cast<uint64_t>(target)) +
                    " out of range (count " + std::to_string(a.count) + ")");
      }
      const std::size_t i = static_cast<std::size_t>(target);
      for (std::size_t c = 0; c < n; ++c) {
        out[i * n + c] = decode(val + k * elementBytes + c * compBytes, a.componentType, a.normalized);
      }
    }
  }
  return out;
}

std::vector<glm::vec3> readVec3(const GltfDocument& doc, int accessor, const std::string& what) {
  const std::vector<double> v = readAccessor(doc, accessor, what);
  if (doc.accessors[accessor].components != 3) Reader(doc, accessor, what).fail("is not VEC3");
  std::vector<glm::vec3> out(v.size() / 3);
  for (std::size_t i = 0; i < out.size(); ++i) out[i] = {v[3 * i], v[3 * i + 1], v[3 * i + 2]};
  return out;
}

std::vector<glm::vec2> readVec2(const GltfDocument& doc, int accessor, const std::string& what) {
  const std::vector<double> v = readAccessor(doc, accessor, what);
  if (doc.accessors[accessor].components != 2) Reader(doc, accessor, what).fail("is not VEC2");
  std::vector<glm::vec2> out(v.size() / 2);
  for (std::size_t i = 0; i < out.size(); ++i) out[i] = {v[2 * i], v[2 * i + 1]};
  return out;
}

std::vector<uint32_t> readIndices(const GltfDocument& doc, int accessor) {
  const std::vector<double> v = readAccessor(doc, accessor, "indices");
  const Accessor& a = doc.accessors[accessor];
  if (a.components != 1 || a.normalized ||
      (a.componentType != kUnsignedByte && a.componentType != kUnsignedShort &&
       a.componentType != kUnsignedInt)) {
    Reader(doc, accessor, "indices").fail("indices must be unsigned integer scalars");
  }
  return std::vector<uint32_t>(v.begin(), v.end());
}

}  // namespace tofsim::scene::detail
