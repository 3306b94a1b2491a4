// Reading speed and peak memory of the log readers on a 4 km well at 2.5 mm
// sampling (1.6 M rows), as column text and as LAS 2.0, against a plain
// single-thread std::from_chars loop over the same file (the practical limit).
//
//   io_read_bench [--length M] [--step M] [--dir DIR] [--threads N] [--keep 1]
//   io_read_bench --read FILE [--threads N]      (one measurement, used by the above)
//   io_read_bench --plain FILE
//
// Each measurement runs in its own process so that its peak resident memory
// (getrusage) is the reader's alone; files are read once first so that all
// figures are from the page cache.
#include <sys/resource.h>

#include <charconv>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <string>
#include <vector>

#include "io/column_text_writer.h"
#include "io/las_writer.h"
#include "io/log_reader.h"
#include "reconstruction/synthetic_well.h"

namespace {

using Clock = std::chrono::steady_clock;

double seconds(Clock::time_point a, Clock::time_point b) { return std::chrono::duration<double>(b - a).count(); }

double peakMiB() {
    rusage usage{};
    getrusage(RUSAGE_SELF, &usage);
    return static_cast<double>(usage.ru_maxrss) / 1024.0;
}

std::size_t tableBytes(const caliper3d::io::SectionTable& t) {
    std::size_t n = t.depth_m.size() + t.radius_mm.size() + t.p1az_deg.size() + t.devi_deg.size() +
                    t.hazi_deg.size() + t.rb_deg.size() + t.bitSize_mm.size();
    for (const auto& e : t.extraCurves) n += e.values.size();
    return n * sizeof(double);
}

int readOne(const std::string& path, int threads) {
    caliper3d::io::ReadOptions options;
    caliper3d::io::StreamOptions stream;
    stream.threads = threads;
    const auto start = Clock::now();
    const caliper3d::io::LoadedLog log = caliper3d::io::loadCaliperLog(path, options, stream);
    const double s = seconds(start, Clock::now());
    const double mb = static_cast<double>(std::filesystem::file_size(path)) / 1e6;
    const double arrays = static_cast<double>(tableBytes(log.table)) / (1024.0 * 1024.0);
    std::printf("RESULT reader %.4f s %.1f MB/s rows %zu arrays %.1f MiB peak %.1f MiB ratio %.2f\n", s, mb / s,
                log.table.rowCount(), arrays, peakMiB(), peakMiB() / arrays);
    return 0;
}

// The practical limit: the same big reads, every number parsed with
// std::from_chars, nothing stored.
int plainLoop(const std::string& path) {
    const auto start = Clock::now();
    std::FILE* f = std::fopen(path.c_str(), "rb");
    if (!f) return 1;
    std::vector<char> buffer(8u << 20);
    std::size_t keep = 0, numbers = 0;
    double sum = 0.0;
    bool data = path.size() < 4 || path.substr(path.size() - 4) != ".las";
    for (;;) {
        const std::size_t got = std::fread(buffer.data() + keep, 1, buffer.size() - keep, f);
        const std::size_t size = keep + got;
        if (size == 0) break;
        std::size_t end = size;
        if (got > 0)
            while (end > 0 && buffer[end - 1] != '\n') --end;
        const char* p = buffer.data();
        const char* last = buffer.data() + end;
        while (p < last) {
            const char* nl = static_cast<const char*>(std::memchr(p, '\n', static_cast<std::size_t>(last - p)));
            if (!nl) nl = last;
            if (!data || *p == '#' || *p == '~') {
                if (*p == '~' && (p[1] == 'A' || p[1] == 'a')) data = true;
                p = nl + 1;
                continue;
            }
            while (p < nl) {
                while (p < nl && (*p == ' ' || *p == '\t')) ++p;
                if (p == nl) break;
                double v = 0.0;
                auto r = std::from_chars(p, nl, v);
                if (r.ec != std::errc()) break;
                sum += v;
                ++numbers;
                p = r.ptr;
            }
            p = nl + 1;
        }
        keep = size - end;
        std::memmove(buffer.data(), buffer.data() + end, keep);
        if (got == 0) break;
    }
    std::fclose(f);
    const double s = seconds(start, Clock::now());
    const double mb = static_cast<double>(std::filesystem::file_size(path)) / 1e6;
    std::printf("RESULT plain %.4f s %.1f MB/s numbers %zu (sum %.3g) peak %.1f MiB\n", s, mb / s, numbers, sum,
                peakMiB());
    return 0;
}

std::string runChild(const std::string& self, const std::string& args) {
    const std::string command = self + " " + args;
    std::FILE* pipe = popen(command.c_str(), "r");
    std::string out;
    char line[512];
    while (pipe && std::fgets(line, sizeof line, pipe)) out += line;
    if (pipe) pclose(pipe);
    return out;
}

}  // namespace

int main(int argc, char** argv) {
    double length = 4000.0, step = 0.0025;
    int threads = 2;
    bool keep = false;
    std::string dir = (std::filesystem::temp_directory_path() / "caliper3d_io_bench").string();
    std::string readPath, plainPath;
    for (int i = 1; i + 1 < argc; i += 2) {
        const std::string a = argv[i];
        if (a == "--length") length = std::atof(argv[i + 1]);
        else if (a == "--step") step = std::atof(argv[i + 1]);
        else if (a == "--dir") dir = argv[i + 1];
        else if (a == "--threads") threads = std::atoi(argv[i + 1]);
        else if (a == "--read") readPath = argv[i + 1];
        else if (a == "--plain") plainPath = argv[i + 1];
        else if (a == "--keep") keep = std::atoi(argv[i + 1]) != 0;
    }
    if (!readPath.empty()) return readOne(readPath, threads);
    if (!plainPath.empty()) return plainLoop(plainPath);

    std::filesystem::create_directories(dir);
    const std::string text = dir + "/well.txt", las = dir + "/well.las";
    {
        const auto start = Clock::now();
        const caliper3d::io::SectionTable well = caliper3d::reconstruction::makeSyntheticWell(
            caliper3d::reconstruction::syntheticProfile("example", length, step));
        caliper3d::io::writeColumnTextFile(text, well, caliper3d::io::LengthUnit::Millimetre);
        caliper3d::io::writeLasFile(las, well);
        std::printf("wrote %zu rows: %s (%.1f MB), %s (%.1f MB) in %.1f s\n", well.rowCount(), text.c_str(),
                    static_cast<double>(std::filesystem::file_size(text)) / 1e6, las.c_str(),
                    static_cast<double>(std::filesystem::file_size(las)) / 1e6, seconds(start, Clock::now()));
    }
    for (const std::string& file : {text, las}) {
        runChild(argv[0], "--plain " + file);  // warm the page cache
        const std::string plain = runChild(argv[0], "--plain " + file);
        const std::string ours = runChild(argv[0], "--read " + file + " --threads " + std::to_string(threads));
        const std::string one = runChild(argv[0], "--read " + file + " --threads 1");
        double plainRate = 0, ourRate = 0, oneRate = 0;
        std::sscanf(std::strstr(plain.c_str(), "s ") ? std::strstr(plain.c_str(), "s ") + 2 : "", "%lf", &plainRate);
        std::sscanf(std::strstr(ours.c_str(), "s ") ? std::strstr(ours.c_str(), "s ") + 2 : "", "%lf", &ourRate);
        std::sscanf(std::strstr(one.c_str(), "s ") ? std::strstr(one.c_str(), "s ") + 2 : "", "%lf", &oneRate);
        std::printf("%s\n  plain from_chars loop: %s  reader, %d threads:  %s  reader, 1 thread:   %s"
                    "  reader / plain = %.2f (%d threads), %.2f (1 thread)\n",
                    file.c_str(), plain.c_str(), threads, ours.c_str(), one.c_str(),
                    plainRate > 0 ? ourRate / plainRate : 0.0, threads, plainRate > 0 ? oneRate / plainRate : 0.0);
    }
    if (!keep) {
        std::filesystem::remove(text);
        std::filesystem::remove(las);
    }
    return 0;
}
