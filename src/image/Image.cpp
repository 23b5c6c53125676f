#include "gridcar/image/Image.h"

#include "gridcar/core/Files.h"
#include "gridcar/core/Limits.h"

#include <cctype>
#include <climits>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <sstream>

#include <stb_image.h>
#include <stb_image_write.h>

namespace gridcar
{
namespace
{
std::vector<std::uint8_t> readFileBytes(const std::string &path)
{
    std::ifstream in(path, std::ios::binary);
    if (!in) throw MapLoadError(path, "cannot open file (" + std::string(std::strerror(errno)) + ")");
    in.seekg(0, std::ios::end);
    const std::streamoff size = in.tellg();
    if (size < 0) throw MapLoadError(path, "cannot determine file size");
    if (size > (std::streamoff(1) << 31)) throw MapLoadError(path, "file larger than 2 GiB");
    in.seekg(0, std::ios::beg);
    std::vector<std::uint8_t> bytes(static_cast<std::size_t>(size));
    if (size > 0 && !in.read(reinterpret_cast<char *>(bytes.data()), size))
        throw MapLoadError(path, "read error");
    return bytes;
}

void checkDims(const std::string &path, long long w, long long h)
{
    if (w <= 0 || h <= 0)
        throw MapLoadError(path, "image dimensions must be positive, got " + std::to_string(w) + " x " +
                                     std::to_string(h));
    if (w > (1 << 20) || h > (1 << 20) || (unsigned long long)w * (unsigned long long)h > kMaxMapCells)
        throw MapLoadError(path, "image dimensions " + std::to_string(w) + " x " + std::to_string(h) +
                                     " exceed the limit of " + std::to_string(kMaxMapCells) + " pixels");
}

/// The bytes ended inside a Netpbm header (so a prefix of the file may simply be too short).
struct TruncatedHeader : MapLoadError
{
    using MapLoadError::MapLoadError;
};

/// Netpbm reader: P2/P3 (ASCII) and P5/P6 (binary), with '#' comments in the header.
class PnmParser
{
public:
    PnmParser(const std::string &path, const std::vector<std::uint8_t> &b) : path_(path), b_(b) {}

    /// Reads the header (magic, width, height, maxval), checks the dimensions, and checks that a
    /// file of @p fileSize bytes can hold the pixel data the header declares: all before
    /// anything is allocated for the pixels (a 39-byte file must not cost 780 MB).
    void header(std::size_t fileSize)
    {
        if (b_.size() < 2 || b_[0] != 'P') throw MapLoadError(path_, "not a Netpbm file (no 'P' magic)");
        kind_ = char(b_[1]);
        if (kind_ != '2' && kind_ != '3' && kind_ != '5' && kind_ != '6')
            throw MapLoadError(path_, std::string("unsupported Netpbm type P") + kind_ +
                                          " (supported: P2, P3, P5, P6)");
        pos_ = 2;
        w_ = headerInt("width"), h_ = headerInt("height"), maxval_ = headerInt("maxval");
        checkDims(path_, w_, h_);
        if (maxval_ < 1 || maxval_ > 65535)
            throw MapLoadError(path_, "maxval must be in 1..65535, got " + std::to_string(maxval_));
        const std::size_t n = std::size_t(w_) * std::size_t(h_) * ((kind_ == '3' || kind_ == '6') ? 3 : 1);
        const bool binary = kind_ == '5' || kind_ == '6';
        // binary: the samples; ASCII: at least one digit and one separator per sample
        const std::size_t need = binary ? n * (maxval_ > 255 ? 2 : 1) + 1 : 2 * n - 1;
        const std::size_t have = fileSize > pos_ ? fileSize - pos_ : 0;
        if (have < need)
            throw MapLoadError(path_, "truncated pixel data: the header declares " + std::to_string(w_) + " x " +
                                          std::to_string(h_) + " pixels, which need at least " + std::to_string(need) +
                                          " more bytes, the file has " + std::to_string(have));
    }

    Image parse()
    {
        header(b_.size());
        const char kind = kind_;
        const long long maxval = maxval_;
        Image img;
        img.width = int(w_);
        img.height = int(h_);
        img.channels = (kind == '3' || kind == '6') ? 3 : 1;
        const std::size_t n = std::size_t(w_) * std::size_t(h_) * std::size_t(img.channels);
        img.data.resize(n);
        if (kind == '5' || kind == '6')
        {
            // exactly one whitespace byte after maxval
            if (pos_ >= b_.size() || !std::isspace(b_[pos_])) throw MapLoadError(path_, "truncated header");
            ++pos_;
            const std::size_t bps = maxval > 255 ? 2 : 1;
            const std::size_t need = n * bps;
            if (b_.size() - pos_ < need)
                throw MapLoadError(path_, "truncated pixel data: expected " + std::to_string(need) +
                                              " bytes, found " + std::to_string(b_.size() - pos_));
            for (std::size_t i = 0; i < n; ++i)
            {
                unsigned v = bps == 1 ? b_[pos_ + i] : (unsigned(b_[pos_ + 2 * i]) << 8) | b_[pos_ + 2 * i + 1];
                img.data[i] = scale(v, unsigned(maxval));
            }
        }
        else
        {
            for (std::size_t i = 0; i < n; ++i)
            {
                const long long v = dataInt(i);
                if (v > maxval) throw MapLoadError(path_, "sample " + std::to_string(v) + " exceeds maxval");
                img.data[i] = scale(unsigned(v), unsigned(maxval));
            }
        }
        return img;
    }

private:
    static std::uint8_t scale(unsigned v, unsigned maxval)
    {
        if (maxval == 255) return std::uint8_t(v);
        return std::uint8_t((v * 255u + maxval / 2) / maxval);
    }

    void skipSpaceAndComments()
    {
        while (pos_ < b_.size())
        {
            if (std::isspace(b_[pos_])) ++pos_;
            else if (b_[pos_] == '#')
                while (pos_ < b_.size() && b_[pos_] != '\n') ++pos_;
            else break;
        }
    }

    long long readInt(const std::string &what)
    {
        skipSpaceAndComments();
        if (pos_ >= b_.size()) throw TruncatedHeader(path_, "truncated: missing " + what);
        if (!std::isdigit(b_[pos_]))
            throw MapLoadError(path_, "bad " + what + ": expected a non-negative integer");
        long long v = 0;
        while (pos_ < b_.size() && std::isdigit(b_[pos_]))
        {
            v = v * 10 + (b_[pos_] - '0');
            if (v > (1LL << 40)) throw MapLoadError(path_, what + " is absurdly large");
            ++pos_;
        }
        return v;
    }
    long long headerInt(const std::string &what) { return readInt("header field " + what); }
    long long dataInt(std::size_t i)
    {
        skipSpaceAndComments();
        if (pos_ >= b_.size())
            throw MapLoadError(path_, "truncated pixel data: only " + std::to_string(i) + " samples");
        return readInt("sample");
    }

    const std::string &path_;
    const std::vector<std::uint8_t> &b_;
    std::size_t pos_{0};
    char kind_{0};
    long long w_{0}, h_{0}, maxval_{0};
};

/// The PNG without its zero-length IDAT chunks (legal, and without data, but stb_image's
/// inflater then does pointer arithmetic on a null pointer: undefined behaviour). Other chunks
/// are copied unchanged; a chunk running past the end is left for stb_image to report.
std::vector<std::uint8_t> withoutEmptyIdat(const std::vector<std::uint8_t> &png)
{
    std::vector<std::uint8_t> out(png.begin(), png.begin() + 8);
    std::size_t i = 8;
    while (i + 12 <= png.size())
    {
        const std::size_t len = (std::size_t(png[i]) << 24) | (std::size_t(png[i + 1]) << 16) | (std::size_t(png[i + 2]) << 8) | png[i + 3];
        const bool emptyIdat = len == 0 && std::memcmp(&png[i + 4], "IDAT", 4) == 0;
        const std::size_t end = len > png.size() - i - 12 ? png.size() : i + 12 + len;
        if (!emptyIdat) out.insert(out.end(), png.begin() + std::ptrdiff_t(i), png.begin() + std::ptrdiff_t(end));
        i = end;
    }
    out.insert(out.end(), png.begin() + std::ptrdiff_t(std::min(i, png.size())), png.end());
    return out;
}

/// A PNG with a chunk longer than the rest of the file, whose compressed data cannot hold the
/// pixels its header declares, or whose data inflates to more than they need, is refused
/// before stb_image decodes it (it allocates for a chunk's declared length, up to 1 GB, before
/// reading it): its inflater reads
/// zeros past the end of the data and grows its buffer (doubling up to 2 GB) for as long as
/// the stream goes on, so a few dozen bytes could make it allocate a gigabyte (found by
/// fuzz_image). Deflate expands at most 1032:1; the data is inflated here into a buffer of the
/// size the header allows, no larger.
void checkPngInflation(const std::string &path, const std::vector<std::uint8_t> &png)
{
    std::vector<char> idat;
    long long w = 0, h = 0, bitsPerPixel = 8, interlaced = 0;
    // stb_image takes any 8 bytes left as a chunk's length and type (with 8-11 bytes at the end
    // it reallocated its data buffer up to 2 GB for an IDAT chunk there: found by fuzz_image)
    for (std::size_t i = 8; i + 8 <= png.size();)
    {
        const std::size_t len = (std::size_t(png[i]) << 24) | (std::size_t(png[i + 1]) << 16) | (std::size_t(png[i + 2]) << 8) | png[i + 3];
        if (std::memcmp(&png[i + 4], "IEND", 4) == 0) break;  // stb_image reads no further
        const std::size_t after = png.size() - i - 8;  // data and CRC must fit in it
        if (len > after || after - len < 4)  // stb_image would allocate for it before noticing
            throw MapLoadError(path, "truncated: chunk '" + std::string(reinterpret_cast<const char *>(&png[i + 4]), 4) +
                                         "' declares " + std::to_string(len) + " bytes and a 4-byte CRC, the file has " +
                                         std::to_string(after) + " after its header");
        const std::uint8_t *d = &png[i + 8];
        if (std::memcmp(&png[i + 4], "IHDR", 4) == 0 && len >= 13 && w == 0)  // the first, as stb_image reads it
        {
            w = (static_cast<long long>(d[0]) << 24) | (d[1] << 16) | (d[2] << 8) | d[3];
            h = (static_cast<long long>(d[4]) << 24) | (d[5] << 16) | (d[6] << 8) | d[7];
            static const int channels[7] = {1, 0, 3, 1, 2, 0, 4};
            bitsPerPixel = d[8] * (d[9] < 7 && channels[d[9]] ? channels[d[9]] : 4);
            interlaced = d[12];
        }
        else if (std::memcmp(&png[i + 4], "IDAT", 4) == 0)
            idat.insert(idat.end(), d, d + len);
        i += 12 + len;
    }
    // stb_image says what is wrong with a header like that (products below stay within 2^62)
    if (w <= 0 || h <= 0 || w > (1LL << 28) || h > (1LL << 28)) return;
    const long long rowBytes = 1 + (w * bitsPerPixel + 7) / 8;
    const long long need = h * rowBytes, bound = need + (interlaced ? 16 * (h + 8) : 0);
    const long long canHold = 1100LL * (long long)(idat.size()) + 1024;
    if (need > canHold)
        throw MapLoadError(path, "the header declares " + std::to_string(w) + " x " + std::to_string(h) + " pixels (" +
                                     std::to_string(need) + " bytes of rows), more than its " +
                                     std::to_string(idat.size()) + " bytes of compressed data can hold");
    if (bound >= (long long)(INT32_MAX)) throw MapLoadError(path, "PNG too large: " + std::to_string(need) + " bytes of pixel rows");
    std::vector<char> out(std::size_t(bound) + 1);
    const int n = stbi_zlib_decode_buffer(out.data(), int(out.size()), idat.data(), int(idat.size()));
    if (n < 0 || n > bound)
        throw MapLoadError(path, "its compressed image data is corrupt or inflates to more than the " + std::to_string(w) +
                                     " x " + std::to_string(h) + " pixels its header declares (" +
                                     (n < 0 ? std::string(stbi_failure_reason()) : std::to_string(n) + " bytes") + ")");
}

void writeToVector(void *ctx, void *data, int size)
{
    auto *v = static_cast<std::vector<std::uint8_t> *>(ctx);
    const auto *p = static_cast<const std::uint8_t *>(data);
    v->insert(v->end(), p, p + size);
}
}  // namespace

Image readImage(const std::string &path)
{
    requireReadableFile(path, "image file");
    {
        // a Netpbm header is checked against the file's size before the file is read whole
        std::ifstream in(path, std::ios::binary);
        std::vector<std::uint8_t> head(4096);
        in.read(reinterpret_cast<char *>(head.data()), std::streamsize(head.size()));
        head.resize(std::size_t(in.gcount()));
        std::error_code ec;
        const auto size = std::filesystem::file_size(path, ec);
        if (!ec && head.size() >= 2 && head[0] == 'P' && std::isdigit(head[1]))
        {
            PnmParser probe(path, head);
            try
            {
                probe.header(std::size_t(size));
            }
            catch (const TruncatedHeader &)
            {
                // a header longer than the probe (long comments) is checked again on the whole file
                if (head.size() >= size) throw;
            }
        }
    }
    std::vector<std::uint8_t> bytes = readFileBytes(path);
    if (bytes.empty()) throw MapLoadError(path, "file is empty");
    static const std::uint8_t pngSig[8] = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1a, '\n'};
    if (bytes.size() >= 8 && std::memcmp(bytes.data(), pngSig, 8) == 0)
    {
        bytes = withoutEmptyIdat(bytes);
        int w = 0, h = 0, comp = 0;
        if (bytes.size() > size_t(INT32_MAX)) throw MapLoadError(path, "PNG too large");
        if (!stbi_info_from_memory(bytes.data(), int(bytes.size()), &w, &h, &comp))
            throw MapLoadError(path, std::string("bad PNG header: ") + stbi_failure_reason());
        checkDims(path, w, h);
        checkPngInflation(path, bytes);
        unsigned char *pix = stbi_load_from_memory(bytes.data(), int(bytes.size()), &w, &h, &comp, 0);
        if (!pix) throw MapLoadError(path, std::string("cannot decode PNG: ") + stbi_failure_reason());
        Image img;
        img.width = w;
        img.height = h;
        img.channels = comp;
        img.data.assign(pix, pix + std::size_t(w) * h * comp);
        stbi_image_free(pix);
        return img;
    }
    if (bytes[0] == 'P') return PnmParser(path, bytes).parse();
    throw MapLoadError(path, "unsupported image format (expected PNG or Netpbm P2/P3/P5/P6)");
}

void writePng(const std::string &path, const Image &img)
{
    if (img.width <= 0 || img.height <= 0 || img.channels < 1 || img.channels > 4)
        throw std::runtime_error(path + ": cannot write an empty image");
    std::vector<std::uint8_t> out;
    stbi_write_png_compression_level = 6;
    if (!stbi_write_png_to_func(writeToVector, &out, img.width, img.height, img.channels, img.data.data(),
                                img.width * img.channels))
        throw std::runtime_error(path + ": PNG encoding failed");
    std::ofstream f(path, std::ios::binary);
    if (!f || !f.write(reinterpret_cast<const char *>(out.data()), std::streamsize(out.size())))
        throw std::runtime_error(path + ": cannot write file (" + std::string(std::strerror(errno)) + ")");
}

void writePgm(const std::string &path, const Image &img)
{
    if (img.channels != 1) throw std::runtime_error(path + ": PGM needs a one-channel image");
    std::ofstream f(path, std::ios::binary);
    if (!f) throw std::runtime_error(path + ": cannot write file (" + std::string(std::strerror(errno)) + ")");
    f << "P5\n# CREATOR: gridcar\n" << img.width << ' ' << img.height << "\n255\n";
    f.write(reinterpret_cast<const char *>(img.data.data()), std::streamsize(img.data.size()));
    if (!f) throw std::runtime_error(path + ": write error");
}

}  // namespace gridcar
