#include "Hdf5Attributes.h"

#include <type_traits>
#include <vector>

#include "Hdf5Handle.h"

namespace tofsim::io::detail {

namespace {

using H5Attr = H5Handle<H5Aclose>;

H5Type utf8Type(const std::filesystem::path& path, const std::string& field) {
  H5Type type(h5Check(H5Tcopy(H5T_C_S1), path, field, "cannot make a string type"));
  h5Check(H5Tset_size(type.get(), H5T_VARIABLE), path, field, "cannot make a string type");
  h5Check(H5Tset_cset(type.get(), H5T_CSET_UTF8), path, field, "cannot make a string type");
  return type;
}

void put(hid_t object, const std::string& name, hid_t fileType, hid_t memType, hid_t space,
         const void* data, const std::filesystem::path& path, const std::string& field) {
  const std::string where = field + " attribute " + name;
  if (h5Check(H5Aexists(object, name.c_str()), path, where, "cannot look the attribute up") > 0) {
    h5Check(H5Adelete(object, name.c_str()), path, where, "cannot replace the attribute");
  }
  const H5Attr attr(
      h5Check(H5Acreate2(object, name.c_str(), fileType, space, H5P_DEFAULT, H5P_DEFAULT), path,
              where, "cannot create the attribute"));
  h5Check(H5Awrite(attr.get(), memType, data), path, where, "cannot write the attribute");
}

}  // namespace

void writeAttribute(hid_t object, const H5Attribute& attribute, const std::filesystem::path& path,
                    const std::string& field) {
  std::visit(
      [&](const auto& value) {
        using T = std::decay_t<decltype(value)>;
        if constexpr (std::is_same_v<T, std::vector<std::string>>) {
          const H5Type type = utf8Type(path, field);
          const hsize_t n = value.size();
          const H5Space space(
              h5Check(H5Screate_simple(1, &n, nullptr), path, field, "cannot make a dataspace"));
          std::vector<const char*> text;
          for (const std::string& s : value) text.push_back(s.c_str());
          put(object, attribute.name, type.get(), type.get(), space.get(), text.data(), path,
              field);
        } else {
          const H5Space space(
              h5Check(H5Screate(H5S_SCALAR), path, field, "cannot make a dataspace"));
          if constexpr (std::is_same_v<T, std::string>) {
            const H5Type type = utf8Type(path, field);
            const char* text = value.c_str();
            put(object, attribute.name, type.get(), type.get(), space.get(), &text, path, field);
          } else if constexpr (std::is_same_v<T, double>) {
            put(object, attribute.name, H5T_IEEE_F64LE, H5T_NATIVE_DOUBLE, space.get(), &value,
                path, field);
          } else {
            put(object, attribute.name, H5T_STD_I64LE, H5T_NATIVE_INT64, space.get(), &value, path,
                field);
          }
        }
      },
      attribute.value);
}

std::optional<std::string> readStringAttribute(hid_t object, const std::string& name,
                                               const std::filesystem::path& path,
                                               const std::string& field) {
  const std::string where = field + " attribute " + name;
  if (h5Check(H5Aexists(object, name.c_str()), path, where, "cannot look the attribute up") <= 0) {
    return std::nullopt;
  }
  const H5Attr attr(h5Check(H5Aopen(object, name.c_str(), H5P_DEFAULT), path, where,
                            "cannot open the attribute"));
  const H5Type type(h5Check(H5Aget_type(attr.get()), path, where, "cannot read its type"));
  const H5Space space(h5Check(H5Aget_space(attr.get()), path, where, "cannot read its shape"));
  if (H5Tget_class(type.get()) != H5T_STRING ||
      H5Sget_simple_extent_type(space.get()) != H5S_SCALAR) {
    throwH5(path, where, "not a scalar string");
  }
  if (H5Tis_variable_str(type.get()) > 0) {
    char* text = nullptr;
    h5Check(H5Aread(attr.get(), type.get(), &text), path, where, "cannot read the attribute");
    std::string value = text ? text : "";
    H5free_memory(text);
    return value;
  }
  const std::size_t size = H5Tget_size(type.get());
  std::string value(size, '\0');
  h5Check(H5Aread(attr.get(), type.get(), value.data()), path, where, "cannot read the attribute");
  value.resize(value.find('\0') == std::string::npos ? size : value.find('\0'));
  return value;
}

}  // namespace tofsim::io::detail
