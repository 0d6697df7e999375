// SPDX-License-Identifier: AGPL-3.0-or-later
// The sizes a VTK XML file's binary data claim, checked against the file
// before VTK allocates for them (see checkVtkXmlData in VtkXmlHeader.h).
#include <lz4.h>
#include <lzma.h>
#include <zlib.h>

#include <algorithm>
#include <array>
#include <cctype>
#include <charconv>
#include <cstring>
#include <fstream>
#include <limits>
#include <map>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "VtkXmlHeader.h"
#include "tetskin/core/Error.h"

namespace tetskin::detail {
namespace {

using Size = std::uint64_t;
constexpr Size kHuge = std::numeric_limits<Size>::max();

Size timesSaturated(Size a, Size b) {
  return b != 0 && a > kHuge / b ? kHuge : a * b;
}

// The most a compressor's block can expand (deflate's limit is 1032:1;
// LZ4's about 255:1; LZMA reached 7023:1 on 64 MB of zeros, xz 6781:1), and
// the few bytes a tiny block may hold more than that.
std::optional<Size> maxExpansion(std::string_view compressor) {
  if (compressor == "vtkZLibDataCompressor") return 1032;
  if (compressor == "vtkLZ4DataCompressor") return 256;
  if (compressor == "vtkLZMADataCompressor") return 8192;
  return std::nullopt;
}
constexpr Size kExpansionSlack = 1024;

// One block of `compressor`'s, decoded into `out` (as large as the block's
// header says it decodes to): the bytes it decoded to, or nullopt where it
// does not decode (VTK's reader fails there too).
std::optional<std::size_t> decompress(std::string_view compressor,
                                      const std::vector<unsigned char>& in,
                                      std::vector<unsigned char>& out) {
  if (compressor == "vtkZLibDataCompressor") {
    uLongf size = static_cast<uLongf>(out.size());
    if (uncompress(out.data(), &size, in.data(), static_cast<uLong>(in.size())) != Z_OK)
      return std::nullopt;
    return size;
  }
  if (compressor == "vtkLZ4DataCompressor") {
    constexpr std::size_t kIntMax = std::numeric_limits<int>::max();
    if (in.size() > kIntMax || out.size() > kIntMax) return std::nullopt;
    const int size = LZ4_decompress_safe(reinterpret_cast<const char*>(in.data()),
                                         reinterpret_cast<char*>(out.data()),
                                         static_cast<int>(in.size()), static_cast<int>(out.size()));
    if (size < 0) return std::nullopt;
    return static_cast<std::size_t>(size);
  }
  if (compressor == "vtkLZMADataCompressor") {
    std::uint64_t memoryLimit = std::uint64_t(1) << 30;
    std::size_t inAt = 0, outAt = 0;
    if (lzma_stream_buffer_decode(&memoryLimit, 0, nullptr, in.data(), &inAt, in.size(), out.data(),
                                  &outAt, out.size()) != LZMA_OK)
      return std::nullopt;
    return outAt;
  }
  return std::nullopt;
}

// An unsigned integer of `size` bytes in the file's byte order.
Size fromBytes(const unsigned char* bytes, Size size, bool bigEndian) {
  Size value = 0;
  for (Size i = 0; i != size; ++i) value |= Size(bytes[bigEndian ? size - 1 - i : i]) << (8 * i);
  return value;
}

// The bytes one value of an array's type takes in its binary data.
Size wordBytes(std::string_view type) {
  if (type.find("64") != std::string_view::npos) return 8;
  if (type.find("32") != std::string_view::npos) return 4;
  if (type.find("16") != std::string_view::npos) return 2;
  return 1;  // Int8, UInt8, String (characters), Bit (counted apart)
}

// The bytes `values` values of `type` take in binary data.
Size bytesFor(std::string_view type, Size values) {
  return type == "Bit" ? values / 8 + (values % 8 != 0) : timesSaturated(values, wordBytes(type));
}

// The decoded bytes of one array's binary data, from a file offset: raw
// (appended) or base64 (inline, or appended with encoding="base64"; white
// space before and between the groups is skipped).
class BinaryData {
 public:
  BinaryData(std::ifstream& in, Size begin, Size end, bool base64)
      : in_(in), at_(begin), end_(std::max(begin, end)), base64_(base64) {}

  // The next n decoded bytes; false if the data end first.
  bool read(unsigned char* out, Size n) {
    if (!base64_) {
      if (n > end_ - at_) return false;
      in_.clear();
      in_.seekg(static_cast<std::streamoff>(at_));
      in_.read(reinterpret_cast<char*>(out), static_cast<std::streamsize>(n));
      at_ += n;
      return static_cast<Size>(in_.gcount()) == n;
    }
    for (Size done = 0; done != n;) {
      if (next_ == decoded_.size() && !decodeGroup()) return false;
      const Size take = std::min<Size>(n - done, decoded_.size() - next_);
      std::memcpy(out + done, decoded_.data() + next_, take);
      next_ += take;
      done += take;
    }
    return true;
  }
  bool skip(Size n) {
    if (!base64_) {
      if (n > end_ - at_) return false;
      at_ += n;
      return true;
    }
    std::array<unsigned char, 4096> scratch{};
    for (; n > 0;) {
      const Size take = std::min<Size>(n, scratch.size());
      if (!read(scratch.data(), take)) return false;
      n -= take;
    }
    return true;
  }
  // A base64 stream starts anew at the next group, as VTK's reader does
  // after a compression header (encoded apart from its blocks).
  void realign() { next_ = decoded_.size(); }
  // At most this many decoded bytes are left.
  Size left() const {
    return base64_ ? (end_ - at_) / 4 * 3 + (decoded_.size() - next_) : end_ - at_;
  }

 private:
  // Decodes the next group of four characters; false at the end of the
  // data or at a character that is not base64 (VTK's reader stops there
  // too).
  bool decodeGroup() {
    std::array<int, 4> sixBits{};
    int padding = 0;
    for (int& bits : sixBits) {
      int c = 0;
      do {
        if (at_ == end_) return false;
        c = nextChar();
      } while (c == ' ' || c == '\t' || c == '\n' || c == '\r');
      if (c == '=') {
        bits = 0;
        ++padding;
        continue;
      }
      bits = sextet(c);
      if (bits < 0 || padding > 0) return false;
    }
    const Size word =
        Size(sixBits[0]) << 18 | Size(sixBits[1]) << 12 | Size(sixBits[2]) << 6 | Size(sixBits[3]);
    decoded_ = {static_cast<unsigned char>(word >> 16), static_cast<unsigned char>(word >> 8),
                static_cast<unsigned char>(word)};
    decoded_.resize(3 - static_cast<std::size_t>(std::min(padding, 2)));
    next_ = 0;
    return true;
  }
  static int sextet(int c) {
    if (c >= 'A' && c <= 'Z') return c - 'A';
    if (c >= 'a' && c <= 'z') return c - 'a' + 26;
    if (c >= '0' && c <= '9') return c - '0' + 52;
    if (c == '+') return 62;
    if (c == '/') return 63;
    return -1;
  }
  int nextChar() {
    if (bufferAt_ == buffer_.size()) {
      buffer_.resize(static_cast<std::size_t>(std::min<Size>(end_ - at_, 1 << 16)));
      in_.clear();
      in_.seekg(static_cast<std::streamoff>(at_));
      in_.read(buffer_.data(), static_cast<std::streamsize>(buffer_.size()));
      buffer_.resize(static_cast<std::size_t>(in_.gcount()));
      bufferAt_ = 0;
      if (buffer_.empty()) {
        at_ = end_;
        return '=';
      }
    }
    ++at_;
    return static_cast<unsigned char>(buffer_[bufferAt_++]);
  }

  std::ifstream& in_;
  Size at_, end_;  // the file offset read next, and where the data end
  bool base64_;
  std::string buffer_;  // base64: file bytes from at_ - bufferAt_
  std::size_t bufferAt_ = 0;
  std::vector<unsigned char> decoded_;  // base64: the current group's bytes
  std::size_t next_ = 0;
};

// Checks one array's binary data against the file, and reads the value of
// index `wanted` when asked (an offsets array's last: how much connectivity
// VTK allocates), where it can.
class ArrayCheck {
 public:
  ArrayCheck(const std::string& file, const VtkXmlLayout& layout, const VtkXmlArray& array)
      : file_(file), layout_(layout), array_(array) {}

  // The bytes the data's header says they decode to; throws where the
  // header claims more than the file can hold.
  Size decodedBytes(BinaryData& data) {
    if (layout_.compressor.empty()) {
      const Size bytes = word(data, "data header");
      if (bytes > data.left())
        fail("its data header claims " + std::to_string(bytes) + " bytes; " +
             std::to_string(data.left()) + " are left in the file");
      return bytes_ = bytes;
    }
    const Size blocks = word(data, "compression header");
    blockBytes_ = word(data, "compression header");
    lastBlockBytes_ = word(data, "compression header");
    if (blocks > data.left() / static_cast<Size>(layout_.headerBytes))
      fail("its compression header claims " + std::to_string(blocks) + " blocks; " +
           std::to_string(data.left()) + " bytes are left in the file");
    if (blocks > 0 && blockBytes_ == 0) fail("its compression header claims blocks of 0 bytes");
    if (lastBlockBytes_ > blockBytes_)
      fail("its compression header claims a last block of " + std::to_string(lastBlockBytes_) +
           " bytes, larger than the others' " + std::to_string(blockBytes_));
    compressed_.resize(static_cast<std::size_t>(blocks));
    Size total = 0;
    for (Size& size : compressed_) {
      size = word(data, "compression header");
      total = size > kHuge - total ? kHuge : total + size;
    }
    data.realign();
    if (total > data.left())
      fail("its compressed blocks claim " + std::to_string(total) + " bytes; " +
           std::to_string(data.left()) + " are left in the file");
    const Size expansion = *maxExpansion(layout_.compressor);
    for (std::size_t b = 0; b != compressed_.size(); ++b)
      if (uncompressedBytes(b) > timesSaturated(compressed_[b], expansion) + kExpansionSlack)
        fail("its block " + std::to_string(b) + " would expand from " +
             std::to_string(compressed_[b]) + " to " + std::to_string(uncompressedBytes(b)) +
             " bytes; " + layout_.compressor + " expands at most " + std::to_string(expansion) +
             " times");
    return bytes_ = blocks == 0 ? 0 : (blocks - 1) * blockBytes_ + uncompressedBytes(blocks - 1);
  }

  // Value `index` of the data, just after decodedBytes() read the header;
  // nullopt where it cannot be read (data VTK cannot read either).
  std::optional<long long> value(BinaryData& data, Size index) {
    const Size size = wordBytes(array_.type);
    const Size at = index * size;
    std::vector<unsigned char> bytes(static_cast<std::size_t>(size));
    if (layout_.compressor.empty()) {
      if (!data.skip(at) || !data.read(bytes.data(), size)) return std::nullopt;
      return decode(bytes.data());
    }
    if (blockBytes_ == 0) return std::nullopt;
    const Size block = at / blockBytes_;
    if (block >= compressed_.size()) return std::nullopt;
    Size before = 0;
    for (Size b = 0; b != block; ++b) before += compressed_[b];
    if (!data.skip(before)) return std::nullopt;
    const std::optional<std::vector<unsigned char>> unpacked = nextBlock(data, block);
    if (!unpacked || at % blockBytes_ + size > unpacked->size()) return std::nullopt;
    return decode(unpacked->data() + at % blockBytes_);
  }

  // How many strings the data of a String array hold (each ends in a 0
  // byte; a last one may not), just after decodedBytes() read the header;
  // where a block does not decode, those before it.
  Size strings(BinaryData& data) {
    Size count = 0;
    bool open = false;  // the last byte seen ends no string
    const auto countIn = [&](const unsigned char* bytes, std::size_t n) {
      count += static_cast<Size>(std::count(bytes, bytes + n, 0));
      if (n > 0) open = bytes[n - 1] != 0;
    };
    if (layout_.compressor.empty()) {
      std::vector<unsigned char> chunk;
      for (Size left = bytes_; left > 0;) {
        chunk.resize(static_cast<std::size_t>(std::min<Size>(left, 1 << 16)));
        if (!data.read(chunk.data(), chunk.size())) break;
        countIn(chunk.data(), chunk.size());
        left -= chunk.size();
      }
    } else {
      for (std::size_t b = 0; b != compressed_.size(); ++b) {
        const std::optional<std::vector<unsigned char>> unpacked = nextBlock(data, b);
        if (!unpacked) break;
        countIn(unpacked->data(), unpacked->size());
      }
    }
    return count + (open ? 1 : 0);
  }

  [[noreturn]] void fail(const std::string& what) const {
    throw Error(file_, array_.line, "array '" + array_.name + "': " + what);
  }

 private:
  Size word(BinaryData& data, const char* header) {
    std::array<unsigned char, 8> bytes{};
    const auto size = static_cast<Size>(layout_.headerBytes);
    if (!data.read(bytes.data(), size)) fail(std::string("the file ends inside its ") + header);
    return fromBytes(bytes.data(), size, layout_.bigEndian);
  }
  // Block `block`, read from where the data stand, decoded; nullopt where
  // it does not decode.
  std::optional<std::vector<unsigned char>> nextBlock(BinaryData& data, std::size_t block) {
    std::vector<unsigned char> packed(static_cast<std::size_t>(compressed_[block]));
    std::vector<unsigned char> unpacked(static_cast<std::size_t>(uncompressedBytes(block)));
    if (!data.read(packed.data(), packed.size())) return std::nullopt;
    const std::optional<std::size_t> size = decompress(layout_.compressor, packed, unpacked);
    if (!size) return std::nullopt;
    unpacked.resize(*size);
    return unpacked;
  }
  Size uncompressedBytes(std::size_t block) const {
    return block + 1 == compressed_.size() && lastBlockBytes_ != 0 ? lastBlockBytes_ : blockBytes_;
  }
  // One value of the array's integer type, in the file's byte order.
  long long decode(const unsigned char* bytes) const {
    const Size size = wordBytes(array_.type);
    const Size raw = fromBytes(bytes, size, layout_.bigEndian);
    if (array_.type.front() == 'U' || size == 8) return static_cast<long long>(raw);
    const Size sign = Size(1) << (8 * size - 1);  // sign-extended
    return static_cast<long long>((raw ^ sign) - sign);
  }

  const std::string& file_;
  const VtkXmlLayout& layout_;
  const VtkXmlArray& array_;
  Size bytes_ = 0;  // the data's decoded bytes
  Size blockBytes_ = 0, lastBlockBytes_ = 0;
  std::vector<Size> compressed_;
};

// An inline ascii array's text: how many values it holds at most (values
// are separated by white space), value `index` where asked, and the
// strings its values spell (a String array's characters, each string ended
// by a 0; a last one may not be).
struct AsciiText {
  Size values = 0;
  std::optional<long long> wanted;
  Size strings = 0;
};
AsciiText readAscii(std::ifstream& in, const VtkXmlArray& array, std::optional<Size> index) {
  AsciiText text;
  std::string token;
  bool open = false;  // the last value ends no string
  const auto endToken = [&] {
    if (token.empty()) return;
    long long value = 0;
    const auto [end, ec] = std::from_chars(token.data(), token.data() + token.size(), value);
    const bool number = ec == std::errc() && end == token.data() + token.size();
    if (index && text.values == *index && number) text.wanted = value;
    open = !(number && value == 0);
    text.strings += open ? 0 : 1;
    ++text.values;
    token.clear();
  };
  in.clear();
  in.seekg(static_cast<std::streamoff>(array.textBegin));
  std::string chunk;
  for (Size left = array.textEnd - array.textBegin; left > 0;) {
    chunk.resize(static_cast<std::size_t>(std::min<Size>(left, 1 << 16)));
    in.read(chunk.data(), static_cast<std::streamsize>(chunk.size()));
    if (in.gcount() <= 0) break;
    chunk.resize(static_cast<std::size_t>(in.gcount()));
    left -= chunk.size();
    for (const char c : chunk) {
      if (std::isspace(static_cast<unsigned char>(c)))
        endToken();
      else if (token.size() < 64)
        token += c;
    }
  }
  endToken();
  text.strings += open ? 1 : 0;
  return text;
}

// The values VTK allocates for an array before reading it, where known.
std::optional<Size> allocatedValues(const VtkXmlArray& array,
                                    const std::map<int, long long>& connectivity) {
  using Role = VtkXmlArray::Role;
  if (array.role == Role::Field || array.role == Role::Sized)
    return timesSaturated(static_cast<Size>(array.tuples), static_cast<Size>(array.components));
  if (array.role == Role::Connectivity) {
    const auto found = connectivity.find(array.cellSection);
    if (found != connectivity.end() && found->second > 0) return static_cast<Size>(found->second);
  }
  return std::nullopt;
}

// VTK's reader stores every string a String array's data hold, into an
// array allocated as its header says (it wrote past its end).
void checkStrings(const ArrayCheck& check, Size strings, Size values) {
  if (strings > values)
    check.fail("its data hold " + std::to_string(strings) + " strings; it is allocated " +
               std::to_string(values));
}

}  // namespace

void checkVtkXmlData(const std::filesystem::path& path, const VtkXmlLayout& layout) {
  const std::string file = path.string();
  if (!layout.compressor.empty() && !maxExpansion(layout.compressor))
    throw Error(file, layout.rootLine,
                "compressor '" + layout.compressor +
                    "' is not one VTK reads (vtkZLibDataCompressor, vtkLZ4DataCompressor, "
                    "vtkLZMADataCompressor)");
  std::ifstream in(path, std::ios::binary);
  if (!in) throw Error(file, 0, "cannot open for reading");
  const Size fileSize = std::filesystem::file_size(path);

  // Two passes: a cell section's connectivity is allocated by its offsets'
  // last value, and VTK writes the connectivity first.
  std::map<int, long long> connectivityValues;  // by cell section
  for (const bool connectivityPass : {false, true}) {
    for (const VtkXmlArray& array : layout.arrays) {
      if ((array.role == VtkXmlArray::Role::Connectivity) != connectivityPass) continue;
      const bool offsets = array.cellSection >= 0 && array.name == "offsets" && array.tuples > 0;
      const std::optional<Size> lastOffset =
          offsets ? std::optional<Size>(static_cast<Size>(array.tuples) - 1) : std::nullopt;
      const std::optional<Size> values = allocatedValues(array, connectivityValues);
      ArrayCheck check(file, layout, array);
      if (array.format == "ascii") {
        const AsciiText text = readAscii(in, array, lastOffset);
        if (values && *values > text.values)
          check.fail("is allocated " + std::to_string(*values) + " values; its text holds " +
                     std::to_string(text.values));
        if (offsets && text.wanted) connectivityValues[array.cellSection] = *text.wanted;
        if (array.type == "String" && values) checkStrings(check, text.strings, *values);
        continue;
      }
      if (array.format != "binary" && array.format != "appended") continue;  // VTK refuses it
      if (array.format == "appended" && !layout.appendedBegin)
        check.fail(
            "its data are appended, but the file's <AppendedData> is missing or empty (cut "
            "short?)");
      const Size begin = array.format == "binary"
                             ? array.textBegin
                             : *layout.appendedBegin + static_cast<Size>(array.offset);
      if (array.offset < 0 || begin > fileSize)
        check.fail("its offset " + std::to_string(array.offset) + " lies past the file's end");
      BinaryData data(in, begin, array.format == "binary" ? array.textEnd : fileSize,
                      array.format == "binary" || layout.appendedBase64);
      const Size decoded = check.decodedBytes(data);
      if (values && bytesFor(array.type, *values) > decoded)
        check.fail("is allocated " + std::to_string(*values) + " values (" +
                   std::to_string(bytesFor(array.type, *values)) + " bytes); its data hold " +
                   std::to_string(decoded) + " bytes");
      if (offsets)
        if (const auto last = check.value(data, *lastOffset))
          connectivityValues[array.cellSection] = *last;
      if (array.type == "String" && values) checkStrings(check, check.strings(data), *values);
    }
  }
}

}  // namespace tetskin::detail
