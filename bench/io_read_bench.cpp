// Reading speed and peak memory of the log readers on a 4 km well at 2.5 mm
// sampling (1.6 M rows), as column text, as LAS 2.0 and as DLIS (RP66 v1, written by
// the tests' DLIS writer), against a plain single-thread std::from_chars loop over the
// same text file (the practical limit; for DLIS, reading the file's bytes and summing them).
//
//   io_read_bench [--length M] [--step M] [--dir DIR] [--threads N] [--repeat N] [--keep 1]
//                 [--reuse 1]   (read the files a kept run wrote instead of writing them again)
//   io_read_bench --read FILE [--threads N]      (one measurement, used by the above)
//   io_read_bench --plain FILE
//
// Each measurement runs in its own process so that its peak resident memory
// (getrusage) is the reader's alone; files are read once first so that all
// figures are from the page cache.
#include <sys/resource.h>

#include <algorithm>
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
#include "reconstruction/synthetic/synthetic_well.h"
#include "support/dlis_writer.h"

namespace {

using Clock = std::chrono::steady_clock;

double seconds(Clock::time_point a, Clock::time_point b) {
    return std::chrono::duration<double>(b - a).count();
}

// User plus system time of this process: unlike wall time, hardly moved by
// other jobs on a shared machine.
double cpuSeconds() {
    rusage usage{};
    getrusage(RUSAGE_SELF, &usage);
    return static_cast<double>(usage.ru_utime.tv_sec + usage.ru_stime.tv_sec) +
           static_cast<double>(usage.ru_utime.tv_usec + usage.ru_stime.tv_usec) / 1e6;
}

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
    std::printf(
        "RESULT reader %.4f s %.1f MB/s rows %zu arrays %.1f MiB peak %.1f MiB ratio %.2f cpu %.3f "
        "s\n",
        s, mb / s, log.table.rowCount(), arrays, peakMiB(), peakMiB() / arrays, cpuSeconds());
    return 0;
}

bool isDlis(const std::string& path) {
    return path.size() > 5 && path.substr(path.size() - 5) == ".dlis";
}

// A binary file's practical limit: the same big reads, every byte summed.
int plainBytes(const std::string& path) {
    const auto start = Clock::now();
    std::FILE* f = std::fopen(path.c_str(), "rb");
    if (!f) return 1;
    std::vector<unsigned char> buffer(8u << 20);
    std::size_t bytes = 0;
    unsigned long long sum = 0;
    for (std::size_t got; (got = std::fread(buffer.data(), 1, buffer.size(), f)) > 0;) {
        for (std::size_t i = 0; i < got; ++i) sum += buffer[i];
        bytes += got;
    }
    std::fclose(f);
    const double s = seconds(start, Clock::now());
    const double mb = static_cast<double>(bytes) / 1e6;
    std::printf("RESULT plain %.4f s %.1f MB/s bytes %zu (sum %llu) peak %.1f MiB cpu %.3f s\n", s,
                mb / s, bytes, sum, peakMiB(), cpuSeconds());
    return 0;
}

// The 4 km well as one DLIS frame: DEPT (m, FDOUBL), R1..RN (mm), P1AZ, DEVI, HAZI, RB
// (deg) and BS (mm) as FSINGL, as a logging company writes a caliper.
void writeDlisWell(const std::string& path, const caliper3d::io::SectionTable& t) {
    namespace dlis = caliper3d::test::dlis;
    dlis::LogicalFileSpec file;
    file.fileId = "IO BENCH";
    file.wellName = t.wellName.empty() ? "CALIPER3D" : t.wellName;
    dlis::FrameSpec frame;
    frame.channels.push_back({"DEPT", "m", "Depth", dlis::FDOUBL, {1}});
    for (int k = 1; k <= t.armCount; ++k)
        frame.channels.push_back({"R" + std::to_string(k), "mm", "Radius", dlis::FSINGL, {1}});
    const std::pair<const char*, const std::vector<double>*> optional[] = {{"P1AZ", &t.p1az_deg},
                                                                           {"DEVI", &t.devi_deg},
                                                                           {"HAZI", &t.hazi_deg},
                                                                           {"RB", &t.rb_deg},
                                                                           {"BS", &t.bitSize_mm}};
    for (const auto& [name, values] : optional)
        if (!values->empty())
            frame.channels.push_back(
                {name, std::string(name) == "BS" ? "mm" : "deg", name, dlis::FSINGL, {1}});
    frame.values.reserve(t.rowCount() * frame.width());
    for (std::size_t row = 0; row < t.rowCount(); ++row) {
        frame.values.push_back(t.depth_m[row]);
        for (int k = 0; k < t.armCount; ++k) frame.values.push_back(t.radii(row)[k]);
        for (const auto& [name, values] : optional)
            if (!values->empty()) frame.values.push_back((*values)[row]);
    }
    file.frames.push_back(std::move(frame));
    dlis::writeDlisFile(path, {file});
}

// The practical limit: the same big reads, every number parsed with
// std::from_chars, nothing stored.
int plainLoop(const std::string& path) {
    if (isDlis(path)) return plainBytes(path);
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
            const char* nl =
                static_cast<const char*>(std::memchr(p, '\n', static_cast<std::size_t>(last - p)));
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
    std::printf("RESULT plain %.4f s %.1f MB/s numbers %zu (sum %.3g) peak %.1f MiB cpu %.3f s\n",
                s, mb / s, numbers, sum, peakMiB(), cpuSeconds());
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

struct Run {
    double rate = 0, cpu = 0, peak = 0, ratio = 0;
};

// Fields of a RESULT line: "... s RATE MB/s ... peak P MiB [ratio R] cpu C s".
Run parseRun(const std::string& line) {
    Run r;
    auto after = [&](const char* key, double& value) {
        const std::size_t at = line.find(key);
        if (at != std::string::npos)
            std::sscanf(line.c_str() + at + std::strlen(key), "%lf", &value);
    };
    after(" s ", r.rate);
    after("peak ", r.peak);
    after("ratio ", r.ratio);
    after("cpu ", r.cpu);
    return r;
}

struct Summary {
    double best = 0, median = 0, worst = 0, cpu = 0, peak = 0;
    std::string ratioText;
};

Summary summarise(std::vector<Run> runs) {
    Summary s;
    if (runs.empty()) return s;
    std::sort(runs.begin(), runs.end(), [](const Run& a, const Run& b) { return a.rate > b.rate; });
    s.best = runs.front().rate;
    s.median = runs[runs.size() / 2].rate;
    s.worst = runs.back().rate;
    s.peak = 0;
    double ratio = 0;
    for (const Run& r : runs) {
        s.peak = std::max(s.peak, r.peak);
        ratio = std::max(ratio, r.ratio);
    }
    char text[64];
    std::snprintf(text, sizeof text, "%.2f x parsed arrays", ratio);
    s.ratioText = text;
    s.cpu = std::min_element(runs.begin(), runs.end(), [](const Run& a, const Run& b) {
                return a.cpu < b.cpu;
            })->cpu;
    return s;
}

}  // namespace

int main(int argc, char** argv) {
    double length = 4000.0, step = 0.0025;
    int threads = 2;
    int repeat = 5;
    bool keep = false, reuse = false;
    std::string dir = (std::filesystem::temp_directory_path() / "caliper3d_io_bench").string();
    std::string readPath, plainPath;
    for (int i = 1; i + 1 < argc; i += 2) {
        const std::string a = argv[i];
        if (a == "--length")
            length = std::atof(argv[i + 1]);
        else if (a == "--step")
            step = std::atof(argv[i + 1]);
        else if (a == "--dir")
            dir = argv[i + 1];
        else if (a == "--threads")
            threads = std::atoi(argv[i + 1]);
        else if (a == "--read")
            readPath = argv[i + 1];
        else if (a == "--plain")
            plainPath = argv[i + 1];
        else if (a == "--keep")
            keep = std::atoi(argv[i + 1]) != 0;
        else if (a == "--reuse")
            reuse = std::atoi(argv[i + 1]) != 0;
        else if (a == "--repeat")
            repeat = std::max(1, std::atoi(argv[i + 1]));
    }
    if (!readPath.empty()) return readOne(readPath, threads);
    if (!plainPath.empty()) return plainLoop(plainPath);

    std::filesystem::create_directories(dir);
    const std::string text = dir + "/well.txt", las = dir + "/well.las",
                      dlisFile = dir + "/well.dlis";
    if (!(reuse && std::filesystem::exists(text) && std::filesystem::exists(las) &&
          std::filesystem::exists(dlisFile))) {
        const auto start = Clock::now();
        const caliper3d::io::SectionTable well = caliper3d::reconstruction::makeSyntheticWell(
            caliper3d::reconstruction::syntheticProfile("example", length, step));
        caliper3d::io::writeColumnTextFile(text, well, caliper3d::io::LengthUnit::Millimetre);
        caliper3d::io::writeLasFile(las, well);
        writeDlisWell(dlisFile, well);
        std::printf("wrote %zu rows: %s (%.1f MB), %s (%.1f MB), %s (%.1f MB) in %.1f s\n",
                    well.rowCount(), text.c_str(),
                    static_cast<double>(std::filesystem::file_size(text)) / 1e6, las.c_str(),
                    static_cast<double>(std::filesystem::file_size(las)) / 1e6, dlisFile.c_str(),
                    static_cast<double>(std::filesystem::file_size(dlisFile)) / 1e6,
                    seconds(start, Clock::now()));
    }
    // Each measurement `repeat` times, interleaved so that load from other jobs
    // falls on all three alike; best and median reported.
    for (const std::string& file : {text, las, dlisFile}) {
        runChild(argv[0], "--plain " + file);  // warm the page cache
        const std::string commands[3] = {"--plain " + file,
                                         "--read " + file + " --threads " + std::to_string(threads),
                                         "--read " + file + " --threads 1"};
        const char* labels[3] = {
            isDlis(file) ? "plain read, bytes summed" : "plain from_chars loop", "",
            "reader, 1 thread"};
        std::vector<Run> runs[3];
        for (int i = 0; i < repeat; ++i)
            for (int k = 0; k < 3; ++k) runs[k].push_back(parseRun(runChild(argv[0], commands[k])));
        std::printf("%s (%.1f MB), %d runs each\n", file.c_str(),
                    static_cast<double>(std::filesystem::file_size(file)) / 1e6, repeat);
        // The files differ in size (DLIS is binary): the median seconds per read compare them.
        const double megabytes = static_cast<double>(std::filesystem::file_size(file)) / 1e6;
        Summary summary[3];
        for (int k = 0; k < 3; ++k) {
            summary[k] = summarise(runs[k]);
            const std::string label =
                k == 1 ? "reader, " + std::to_string(threads) + " threads" : labels[k];
            std::printf(
                "  %-24s best %6.1f MB/s  median %6.1f (%.3f s)  worst %6.1f  cpu %.3f s  peak "
                "%.1f "
                "MiB%s\n",
                label.c_str(), summary[k].best, summary[k].median, megabytes / summary[k].median,
                summary[k].worst, summary[k].cpu, summary[k].peak,
                k == 0 ? "" : (" (" + summary[k].ratioText + ")").c_str());
        }
        std::printf(
            "  reader / plain: best %.2f, median %.2f (%d threads); best %.2f, median %.2f (1 "
            "thread)\n",
            summary[1].best / summary[0].best, summary[1].median / summary[0].median, threads,
            summary[2].best / summary[0].best, summary[2].median / summary[0].median);
    }
    if (!keep) {
        std::filesystem::remove(text);
        std::filesystem::remove(las);
        std::filesystem::remove(dlisFile);
    }
    return 0;
}
