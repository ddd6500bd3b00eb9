// CBOR <-> JSON through libcbor (docs/serve.md, "HoloPlay Service protocol").
#include "serve/cbor_json.hpp"

#include <cbor.h>

#include <cstdlib>
#include <memory>
#include <string>

#include "util/error.hpp"

namespace lfd::serve {

namespace {

using json = nlohmann::json;

// The streaming pre-check: a stack of the items each open container still expects (-1 for
// indefinite ones); a tag is a container of one.
struct Precheck {
  const CborLimits* limits = nullptr;
  std::vector<std::int64_t> open;
  std::size_t items = 0;
  std::size_t bytes_left = 0;
  bool done = false;
  const char* error = nullptr;

  void fail(const char* why) {
    if (!error) error = why;
  }
  void item_done() {
    if (++items > limits->max_items) fail("more items than the limit");
    while (!open.empty()) {
      if (open.back() < 0 || --open.back() > 0) return;
      open.pop_back();
    }
    done = true;
  }
  void open_container(std::uint64_t count) {
    if (count == 0) return item_done();
    if (count > bytes_left) return fail("a container claims more items than bytes remain");
    open.push_back(static_cast<std::int64_t>(count));
    if (static_cast<int>(open.size()) > limits->max_depth) fail("nesting deeper than the limit");
  }
  void open_indefinite() {
    open.push_back(-1);
    if (static_cast<int>(open.size()) > limits->max_depth) fail("nesting deeper than the limit");
  }
  void close_indefinite() {
    if (open.empty() || open.back() != -1) return fail("a break outside an indefinite item");
    open.pop_back();
    item_done();
  }
};

Precheck* ctx(void* c) { return static_cast<Precheck*>(c); }
template <typename T>
void on_value(void* c, T) { ctx(c)->item_done(); }
void on_simple(void* c) { ctx(c)->item_done(); }
void on_chunk(void* c, cbor_data, std::size_t) { ctx(c)->item_done(); }
void on_indefinite(void* c) { ctx(c)->open_indefinite(); }
void on_array(void* c, std::size_t n) { ctx(c)->open_container(n); }
void on_map(void* c, std::size_t n) {
  if (n > SIZE_MAX / 2) return ctx(c)->fail("a map claims more items than bytes remain");
  ctx(c)->open_container(2 * static_cast<std::uint64_t>(n));
}
void on_tag(void* c, std::uint64_t) { ctx(c)->open_container(1); }
void on_break(void* c) { ctx(c)->close_indefinite(); }

cbor_callbacks precheck_callbacks() {
  cbor_callbacks cb = cbor_empty_callbacks;
  cb.uint8 = on_value<std::uint8_t>;
  cb.uint16 = on_value<std::uint16_t>;
  cb.uint32 = on_value<std::uint32_t>;
  cb.uint64 = on_value<std::uint64_t>;
  cb.negint8 = on_value<std::uint8_t>;
  cb.negint16 = on_value<std::uint16_t>;
  cb.negint32 = on_value<std::uint32_t>;
  cb.negint64 = on_value<std::uint64_t>;
  cb.byte_string_start = on_indefinite;
  cb.byte_string = on_chunk;
  cb.string_start = on_indefinite;
  cb.string = on_chunk;
  cb.indef_array_start = on_indefinite;
  cb.array_start = on_array;
  cb.indef_map_start = on_indefinite;
  cb.map_start = on_map;
  cb.tag = on_tag;
  cb.float2 = on_value<float>;
  cb.float4 = on_value<float>;
  cb.float8 = on_value<double>;
  cb.undefined = on_simple;
  cb.null = on_simple;
  cb.boolean = on_value<bool>;
  cb.indef_break = on_break;
  return cb;
}

void precheck(std::span<const std::uint8_t> bytes, const CborLimits& limits) {
  static const cbor_callbacks callbacks = precheck_callbacks();
  Precheck state;
  state.limits = &limits;
  std::size_t offset = 0;
  while (!state.done && !state.error) {
    if (offset >= bytes.size()) throw_input_error("CBOR: the message ends inside an item");
    state.bytes_left = bytes.size() - offset;
    const cbor_decoder_result r =
        cbor_stream_decode(bytes.data() + offset, bytes.size() - offset, &callbacks, &state);
    if (r.status != CBOR_DECODER_FINISHED || r.read == 0)
      throw_input_error("CBOR: {} at byte {}",
                        r.status == CBOR_DECODER_NEDATA ? "the message ends inside an item"
                                                        : "malformed item",
                        offset);
    offset += r.read;
  }
  if (state.error) throw_input_error("CBOR: {}", state.error);
  if (offset != bytes.size()) throw_input_error("CBOR: {} bytes after the message", bytes.size() - offset);
}

struct ItemRef {
  void operator()(cbor_item_t* item) const { cbor_decref(&item); }
};
using Item = std::unique_ptr<cbor_item_t, ItemRef>;

std::string text_of(cbor_item_t* item) {
  if (cbor_string_is_definite(item))
    return {reinterpret_cast<const char*>(cbor_string_handle(item)), cbor_string_length(item)};
  std::string out;
  cbor_item_t** chunks = cbor_string_chunks_handle(item);
  for (std::size_t i = 0; i < cbor_string_chunk_count(item); ++i) out += text_of(chunks[i]);
  return out;
}

void append_bytes(cbor_item_t* item, json::binary_t& out) {
  if (cbor_bytestring_is_definite(item)) {
    const auto* p = cbor_bytestring_handle(item);
    out.insert(out.end(), p, p + cbor_bytestring_length(item));
    return;
  }
  cbor_item_t** chunks = cbor_bytestring_chunks_handle(item);
  for (std::size_t i = 0; i < cbor_bytestring_chunk_count(item); ++i) append_bytes(chunks[i], out);
}

json to_json(cbor_item_t* item);

json map_to_json(cbor_item_t* item) {
  json out = json::object();
  cbor_pair* pairs = cbor_map_handle(item);
  for (std::size_t i = 0; i < cbor_map_size(item); ++i) {
    if (!cbor_isa_string(pairs[i].key)) throw_input_error("CBOR: a map key is not text");
    out[text_of(pairs[i].key)] = to_json(pairs[i].value);
  }
  return out;
}

json simple_to_json(cbor_item_t* item) {
  if (cbor_float_ctrl_is_ctrl(item)) {
    if (cbor_is_bool(item)) return cbor_get_bool(item);
    return nullptr;  // null, undefined and other simple values
  }
  return cbor_float_get_float(item);
}

// Depth is bounded by the pre-check, so the recursion is too.
json to_json(cbor_item_t* item) {
  switch (cbor_typeof(item)) {
    case CBOR_TYPE_UINT:
      return static_cast<std::uint64_t>(cbor_get_int(item));
    case CBOR_TYPE_NEGINT: {
      const std::uint64_t v = cbor_get_int(item);
      if (v > static_cast<std::uint64_t>(INT64_MAX)) return -1.0 - static_cast<double>(v);
      return -1 - static_cast<std::int64_t>(v);
    }
    case CBOR_TYPE_BYTESTRING: {
      json::binary_t bytes;
      append_bytes(item, bytes);
      return json::binary(std::move(bytes));
    }
    case CBOR_TYPE_STRING:
      return text_of(item);
    case CBOR_TYPE_ARRAY: {
      json out = json::array();
      cbor_item_t** elements = cbor_array_handle(item);
      for (std::size_t i = 0; i < cbor_array_size(item); ++i) out.push_back(to_json(elements[i]));
      return out;
    }
    case CBOR_TYPE_MAP:
      return map_to_json(item);
    case CBOR_TYPE_TAG: {
      Item tagged{cbor_tag_item(item)};
      return to_json(tagged.get());
    }
    case CBOR_TYPE_FLOAT_CTRL:
      return simple_to_json(item);
  }
  throw_input_error("CBOR: unknown item type");
}

Item from_json(const json& value);

Item map_from_json(const json& value) {
  Item map{cbor_new_definite_map(value.size())};
  if (!map) throw std::bad_alloc();
  for (const auto& [key, v] : value.items()) {
    Item k{cbor_build_stringn(key.data(), key.size())};
    Item val = from_json(v);
    if (!k || !cbor_map_add(map.get(), cbor_pair{k.get(), val.get()})) throw std::bad_alloc();
  }
  return map;
}

Item from_json(const json& value) {
  Item out;
  switch (value.type()) {
    case json::value_t::object:
      return map_from_json(value);
    case json::value_t::array: {
      out.reset(cbor_new_definite_array(value.size()));
      if (!out) throw std::bad_alloc();
      for (const auto& v : value) {
        Item e = from_json(v);
        if (!cbor_array_push(out.get(), e.get())) throw std::bad_alloc();
      }
      return out;
    }
    case json::value_t::string: {
      const auto& s = value.get_ref<const std::string&>();
      out.reset(cbor_build_stringn(s.data(), s.size()));
      break;
    }
    case json::value_t::binary: {
      const auto& b = value.get_binary();
      out.reset(cbor_build_bytestring(b.data(), b.size()));
      break;
    }
    case json::value_t::boolean:
      out.reset(cbor_build_bool(value.get<bool>()));
      break;
    case json::value_t::number_unsigned:
      out.reset(cbor_build_uint64(value.get<std::uint64_t>()));
      break;
    case json::value_t::number_integer: {
      const std::int64_t v = value.get<std::int64_t>();
      out.reset(v >= 0 ? cbor_build_uint64(static_cast<std::uint64_t>(v))
                       : cbor_build_negint64(static_cast<std::uint64_t>(-(v + 1))));
      break;
    }
    case json::value_t::number_float:
      out.reset(cbor_build_float8(value.get<double>()));
      break;
    default:
      out.reset(cbor_new_null());
  }
  if (!out) throw std::bad_alloc();
  return out;
}

}  // namespace

nlohmann::json decode_cbor(std::span<const std::uint8_t> bytes, const CborLimits& limits) {
  if (bytes.empty()) throw_input_error("CBOR: empty message");
  precheck(bytes, limits);
  cbor_load_result result{};
  Item root{cbor_load(bytes.data(), bytes.size(), &result)};
  if (!root || result.error.code != CBOR_ERR_NONE)
    throw_input_error("CBOR: malformed message (libcbor error {} at byte {})",
                      static_cast<int>(result.error.code), result.error.position);
  return to_json(root.get());
}

std::vector<std::uint8_t> encode_cbor(const nlohmann::json& value) {
  Item item = from_json(value);
  unsigned char* buffer = nullptr;
  std::size_t capacity = 0;
  const std::size_t length = cbor_serialize_alloc(item.get(), &buffer, &capacity);
  std::unique_ptr<unsigned char, decltype(&std::free)> owned(buffer, &std::free);
  if (length == 0) throw std::bad_alloc();
  return {buffer, buffer + length};
}

}  // namespace lfd::serve
