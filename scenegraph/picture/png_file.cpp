#include "scenegraph/picture/png_file.h"

#include <cstdio>
#include <memory>
#include <stdexcept>

#include <png.h>

#include "io/atomic_output.h"

namespace caliper3d::scenegraph {

namespace {

using File = std::unique_ptr<std::FILE, int (*)(std::FILE*)>;

// libpng reports errors through longjmp by default; the simplified API (png_image_*) used here
// returns them instead, so no longjmp crosses C++ frames.
std::runtime_error pngError(const std::string& path, const png_image& image, const char* what) {
    return std::runtime_error(path + ": " + what + " (" + image.message + ")");
}

}  // namespace

void writePng(const RenderedImage& image, const std::string& path) {
    if (image.width <= 0 || image.height <= 0 ||
        image.rgba.size() != static_cast<std::size_t>(image.width) * image.height * 4)
        throw std::runtime_error(path + ": no picture to write");
    // Whole or not at all: a killed or failed write leaves the previous picture.
    io::AtomicOutput output(path);
    File file(std::fopen(output.path().c_str(), "wb"), &std::fclose);
    if (!file) throw std::runtime_error(path + ": cannot write the PNG file");
    png_image png{};
    png.version = PNG_IMAGE_VERSION;
    png.width = static_cast<png_uint_32>(image.width);
    png.height = static_cast<png_uint_32>(image.height);
    png.format = PNG_FORMAT_RGBA;
    if (!png_image_write_to_stdio(&png, file.get(), 0, image.rgba.data(), 0, nullptr))
        throw pngError(path, png, "cannot write the PNG file");
    if (std::fflush(file.get()) != 0 || std::ferror(file.get()) || std::fclose(file.release()) != 0)
        throw std::runtime_error(path + ": cannot write the PNG file");
    output.commit();
}

RenderedImage readPng(const std::string& path) {
    png_image png{};
    png.version = PNG_IMAGE_VERSION;
    if (!png_image_begin_read_from_file(&png, path.c_str()))
        throw pngError(path, png, "cannot read the PNG file");
    png.format = PNG_FORMAT_RGBA;
    RenderedImage out;
    out.width = static_cast<int>(png.width);
    out.height = static_cast<int>(png.height);
    out.rgba.resize(PNG_IMAGE_SIZE(png));
    if (!png_image_finish_read(&png, nullptr, out.rgba.data(), 0, nullptr)) {
        png_image_free(&png);
        throw pngError(path, png, "cannot read the PNG file");
    }
    return out;
}

}  // namespace caliper3d::scenegraph
