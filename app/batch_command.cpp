#include <algorithm>
#include <cerrno>
#include <cstdio>
#include <deque>
#include <filesystem>
#include <fstream>
#include <map>
#include <optional>
#include <sstream>
#include <thread>
#include <utility>

#include <sys/wait.h>
#include <unistd.h>

#include <nlohmann/json.hpp>

#include "app/batch_manifest.h"
#include "app/child_process.h"
#include "app/commands.h"
#include "app/huge_pages.h"
#include "app/input_options.h"
#include "app/input_summary.h"
#include "app/progress_display.h"
#include "app/verb_parser.h"
#include "io/parse_error.h"

namespace caliper3d::app {

namespace {

namespace fs = std::filesystem;
using Json = nlohmann::ordered_json;

std::string readWhole(const fs::path& path) {
    std::ifstream in(path, std::ios::binary);
    std::ostringstream text;
    text << in.rdbuf();
    return text.str();
}

// The last line of a child's standard error that says something: why it failed.
std::string lastLine(const std::string& text) {
    std::istringstream in(text);
    std::string line, last;
    while (std::getline(in, line))
        if (line.find_first_not_of(" \t\r") != std::string::npos) last = line;
    return last;
}

// A summary line with the manifest row first.
Json withRow(const ManifestRow& row, const Json& line) {
    Json out;
    out["row"] = row.index;
    for (const auto& [key, value] : line.items()) out[key] = value;
    return out;
}

Json failedLine(const ManifestRow& row, const std::string& verb, const InputError& error) {
    InputSummary summary;
    summary.file = row.file;
    summary.verb = verb;
    summary.error = error;
    return withRow(row, toJson(summary));
}

// A manifest row's verb (one of batchVerbs()), in the process that runs it.
int runBatchVerb(const QString& verb, const QStringList& args) {
    if (verb == "info") return runInfo(args);
    if (verb == "report") return runReport(args);
    if (verb == "render") return runRender(args);
    return runExport(args);
}

struct BatchSettings {
    std::string folder;  // batch -o
    std::size_t jobs = 1;
    int threadsPerWell = 1;
    fs::path scratch;
    std::string manifest;
};

// A row under way: its verbs run in turn, each in a child process of this program.
struct RowRun {
    const ManifestRow* row = nullptr;
    std::size_t verb = 0;  // the one running
    std::vector<Json> lines;
    std::string out, err;  // what its children printed
    double start_s = 0.0;
    fs::path stem() const {
        return "row-" + std::to_string(row->index) + "-" + std::to_string(verb);
    }
};

// Starts the row's current verb; false (and its failed line recorded) where it cannot run.
bool startVerb(RowRun& run, const BatchSettings& settings, pid_t& pid) {
    const ManifestRow& row = *run.row;
    const std::string& verb = row.verbs[run.verb];
    try {
        const std::string output = rowOutput(row, verb, settings.folder);
        const fs::path folder = fs::path(output).parent_path();
        if (!output.empty() && !folder.empty()) fs::create_directories(folder);
        std::vector<std::string> args = {verb};
        // Each well's analysis threads within its share of the cores. Given before the row's
        // own options: the verb's parser takes an option's last value, so a --threads among
        // them wins.
        if (verb == "report")
            args.insert(args.end(), {"--threads", std::to_string(settings.threadsPerWell)});
        const std::vector<std::string> verbArgs =
            verbArguments(row, verb, output, (settings.scratch / run.stem()).string() + ".jsonl");
        args.insert(args.end(), verbArgs.begin(), verbArgs.end());
        const fs::path base = settings.scratch / run.stem();
        const QString name = QString::fromStdString(args.front());
        QStringList qtArgs;
        for (std::size_t k = 1; k < args.size(); ++k) qtArgs << QString::fromStdString(args[k]);
        pid = forkChild([&name, &qtArgs] { return runBatchVerb(name, qtArgs); },
                        base.string() + ".out", base.string() + ".err");
        return true;
    } catch (const std::exception& e) {
        run.lines.push_back(failedLine(row, verb, {settings.manifest, row.line, e.what()}));
        run.err += "caliper3d batch: " + settings.manifest + ":" + std::to_string(row.line) + ": " +
                   e.what() + "\n";
        return false;
    }
}

// Gathers what the row's current verb left: its summary lines (or one saying why there are
// none), its printed text.
void collectVerb(RowRun& run, const BatchSettings& settings, int waitStatus) {
    const ManifestRow& row = *run.row;
    const std::string& verb = row.verbs[run.verb];
    const fs::path base = settings.scratch / run.stem();
    run.out += readWhole(base.string() + ".out");
    const std::string err = readWhole(base.string() + ".err");
    run.err += err;
    std::vector<Json> lines;
    std::istringstream in(readWhole(base.string() + ".jsonl"));
    bool failed = false;
    for (std::string text; std::getline(in, text);) {
        if (text.empty()) continue;
        Json line = Json::parse(text, nullptr, false);
        if (line.is_discarded()) continue;
        failed = failed || line.value("status", "") != "ok";
        lines.push_back(withRow(row, line));
    }
    const std::string end = describeEnd(waitStatus);
    if (!end.empty() && !failed) {
        // It ended badly without saying which input failed: bad usage (from the row's fields:
        // the manifest's line is at fault), a crash.
        const std::string why = lastLine(err);
        const bool usage = WIFEXITED(waitStatus) && WEXITSTATUS(waitStatus) == kExitUsage;
        InputError error{row.file, 0, why.empty() ? verb + ": " + end : why + " (" + end + ")"};
        if (usage) error = {settings.manifest, row.line, why.empty() ? end : why};
        lines = {failedLine(row, verb, error)};
    }
    run.lines.insert(run.lines.end(), lines.begin(), lines.end());
}

bool rowFailed(const std::vector<Json>& lines) {
    return std::any_of(lines.begin(), lines.end(),
                       [](const Json& line) { return line.value("status", "") != "ok"; });
}

// Runs `rows`, `settings.jobs` at a time, writing their summary lines in row order.
int runRows(const std::vector<const ManifestRow*>& rows, const BatchSettings& settings,
            SummaryFile& summaries) {
    std::deque<std::size_t> pending;
    for (std::size_t i = 0; i < rows.size(); ++i) pending.push_back(i);
    std::map<pid_t, std::pair<std::size_t, RowRun>> running;  // pid -> (place in rows, run)
    std::vector<std::optional<std::vector<Json>>> done(rows.size());
    std::size_t written = 0, failures = 0;
    ProgressDisplay progress(rows.size());
    auto finish = [&](std::size_t place, RowRun& run) {
        progress.clear();
        std::fputs(run.out.c_str(), stdout);
        std::fflush(stdout);
        std::fputs(run.err.c_str(), stderr);
        const bool failed = rowFailed(run.lines);
        failures += failed ? 1 : 0;
        done[place] = std::move(run.lines);
        for (; written < done.size() && done[written]; ++written)
            for (const Json& line : *done[written]) summaries.write(line);
        progress.finished(std::to_string(place), !failed);
    };
    // Starts the run's verbs from its current one until one is under way; false: none left.
    auto advance = [&](std::size_t place, RowRun run) {
        for (; run.verb < run.row->verbs.size(); ++run.verb) {
            pid_t pid = 0;
            if (startVerb(run, settings, pid)) {
                running.emplace(pid, std::make_pair(place, std::move(run)));
                return;
            }
        }
        finish(place, run);
    };
    while (!pending.empty() || !running.empty()) {
        while (running.size() < settings.jobs && !pending.empty()) {
            const std::size_t place = pending.front();
            pending.pop_front();
            RowRun run;
            run.row = rows[place];
            run.start_s = steadySeconds();
            progress.started(std::to_string(place), fs::path(run.row->file).filename().string());
            if (!run.row->problem.empty()) {
                run.lines.push_back(
                    failedLine(*run.row, run.row->verbs.front(),
                               {settings.manifest, run.row->line, run.row->problem}));
                run.err = "caliper3d batch: " + settings.manifest + ":" +
                          std::to_string(run.row->line) + ": " + run.row->problem + "\n";
                finish(place, run);
                continue;
            }
            advance(place, std::move(run));
        }
        if (running.empty()) continue;
        int status = 0;
        const pid_t pid = waitpid(-1, &status, progress.enabled() ? WNOHANG : 0);
        if (pid < 0 && errno == EINTR) continue;
        if (pid < 0) throw std::runtime_error("waiting for the wells' processes failed");
        if (pid == 0) {
            std::this_thread::sleep_for(std::chrono::milliseconds(100));
            progress.redraw();
            continue;
        }
        const auto it = running.find(pid);
        if (it == running.end()) continue;
        auto [place, run] = std::move(it->second);
        running.erase(it);
        collectVerb(run, settings, status);
        ++run.verb;
        advance(place, std::move(run));
    }
    progress.clear();
    return static_cast<int>(failures);
}

// batch --merge: the lines of `inputs` in manifest row order (lines without a row last, as
// they came), to `out`.
int mergeSummaries(const std::string& out, const std::vector<std::string>& inputs) {
    std::vector<std::pair<std::size_t, Json>> lines;
    for (const std::string& input : inputs) {
        std::ifstream in(input, std::ios::binary);
        if (!in) throw io::ParseError(input, 0, 0, "cannot open the summary");
        std::size_t lineNumber = 0;
        for (std::string text; std::getline(in, text);) {
            ++lineNumber;
            if (text.find_first_not_of(" \t\r") == std::string::npos) continue;
            Json line = Json::parse(text, nullptr, false);
            if (line.is_discarded() || !line.is_object())
                throw io::ParseError(input, lineNumber, 0, "expected one JSON object a line");
            const Json row = line.value("row", Json());
            const std::size_t key =
                row.is_number_unsigned() ? row.get<std::size_t>() : static_cast<std::size_t>(-1);
            lines.emplace_back(key, std::move(line));
        }
    }
    std::stable_sort(lines.begin(), lines.end(),
                     [](const auto& a, const auto& b) { return a.first < b.first; });
    SummaryFile file(out);
    for (const auto& line : lines) file.write(line.second);
    std::printf("wrote %s (%zu lines from %zu files)\n", out.c_str(), lines.size(), inputs.size());
    return kExitOk;
}

void addBatchOptions(QCommandLineParser& p) {
    p.addOption({{"o", "output"},
                 "Folder for the rows without an output of their own: each verb writes "
                 "DIR/STEM.csv (report), .png (render) or .iv (export).",
                 "DIR/"});
    p.addOption({{"j", "jobs"},
                 "Wells processed at a time, each in its own process (default 1); a report's "
                 "analysis threads share the cores among them.",
                 "N",
                 "1"});
    p.addOption({"row",
                 "Run only data row K of the manifest, counted from 0 (the first well is row "
                 "0): a cluster array's task index (SLURM_ARRAY_TASK_ID with --array=0-(N-1), "
                 "Kubernetes' JOB_COMPLETION_INDEX). FIRST-LAST runs that block of rows in "
                 "one process (LAST past the manifest's end stops at its last row).",
                 "K|FIRST-LAST"});
    p.addOption({"merge",
                 "Write the summary lines of the files given (instead of a manifest) to OUT in "
                 "manifest row order: what the tasks of a cluster array wrote, in one file.",
                 "OUT.jsonl"});
    addSummaryOption(p);
}

std::size_t wholeNumber(VerbParser& verb, const char* name, std::size_t lo, std::size_t hi) {
    bool ok = false;
    const long long value = verb.parser().value(name).toLongLong(&ok);
    if (!ok || value < static_cast<long long>(lo) || value > static_cast<long long>(hi))
        throw UsageError("caliper3d batch: --" + std::string(name) + " takes a whole number from " +
                         std::to_string(lo) + " to " + std::to_string(hi) + ", found '" +
                         verb.value(name) + "'");
    return static_cast<std::size_t>(value);
}

// The rows --row names: K, or FIRST-LAST with LAST past the end cut to the last row, so that
// a cluster array of blocks (task i: rows i*B to i*B+B-1) needs no care for the last block.
std::pair<std::size_t, std::size_t> rowRange(VerbParser& verb, std::size_t rowCount) {
    const QString value = verb.parser().value("row");
    const qsizetype dash = value.indexOf('-', 1);
    if (dash < 0) {
        const std::size_t row = wholeNumber(verb, "row", 0, rowCount - 1);
        return {row, row};
    }
    bool okFirst = false, okLast = false;
    const long long first = value.left(dash).toLongLong(&okFirst);
    const long long last = value.mid(dash + 1).toLongLong(&okLast);
    if (!okFirst || !okLast || first < 0 || last < first ||
        first > static_cast<long long>(rowCount) - 1)
        throw UsageError("caliper3d batch: --row takes K or FIRST-LAST with FIRST from 0 to " +
                         std::to_string(rowCount - 1) + " and LAST >= FIRST, found '" +
                         verb.value("row") + "'");
    return {static_cast<std::size_t>(first),
            std::min(static_cast<std::size_t>(last), rowCount - 1)};
}

}  // namespace

int runBatch(const QStringList& args) {
    return guardedVerb("batch", [&]() -> int {
        VerbParser verb(
            "batch", "MANIFEST [-o DIR/] [-j N] [--row K|FIRST-LAST] [--summary FILE.jsonl]",
            "Run the verbs of a manifest, one well a row (CSV, or JSON for a name ending .json; "
            "docs/formats.md, \"Batch manifests\"), each in a child process of this program, "
            "so that a crash or a failed picture in one well leaves the others running. Bad "
            "rows get their summary line with the reason and the run goes on; the exit status "
            "is 1 when any row failed.\n"
            "caliper3d batch --merge OUT.jsonl IN.jsonl...: the summary lines of a cluster "
            "array's tasks in one file, in manifest row order.");
        QCommandLineParser& p = verb.parser();
        addBatchOptions(p);
        if (!verb.parse(args, 1)) return kExitOk;
        const std::vector<std::string> positional = verb.positional();
        if (verb.isSet("merge")) {
            for (const char* name : {"output", "row", "summary"})
                if (verb.isSet(name))
                    throw UsageError(std::string("caliper3d batch: --merge takes no --") + name);
            return mergeSummaries(verb.value("merge"), positional);
        }
        if (positional.size() != 1)
            throw UsageError("caliper3d batch: give one MANIFEST (found " +
                             std::to_string(positional.size()) + ")");
        // Its wells' arrays in huge pages, however small the manifest (app/huge_pages.h).
        std::vector<std::string> restartArgs = {"caliper3d", "batch"};
        for (const QString& arg : args) restartArgs.push_back(arg.toStdString());
        restartWithHugePageMalloc(hugePageContext(0, 0), restartArgs);
        BatchSettings settings;
        settings.manifest = positional.front();
        settings.folder = verb.isSet("output") ? verb.value("output") : "";
        settings.jobs = wholeNumber(verb, "jobs", 1, 256);
        const std::size_t cores = std::max(1u, std::thread::hardware_concurrency());
        settings.threadsPerWell = static_cast<int>(std::max<std::size_t>(1, cores / settings.jobs));
        const Manifest manifest = readManifest(settings.manifest);
        std::vector<const ManifestRow*> rows;
        for (const ManifestRow& row : manifest.rows) rows.push_back(&row);
        if (verb.isSet("row")) {
            if (manifest.rows.empty())
                throw UsageError("caliper3d batch: --row: " + settings.manifest + " has no rows");
            const auto [first, last] = rowRange(verb, manifest.rows.size());
            rows.assign(rows.begin() + static_cast<std::ptrdiff_t>(first),
                        rows.begin() + static_cast<std::ptrdiff_t>(last) + 1);
        }
        SummaryFile summaries(verb.isSet("summary") ? verb.value("summary") : "");
        char scratch[] = "/tmp/caliper3d-batch-XXXXXX";
        if (const char* folder = mkdtemp(scratch))
            settings.scratch = folder;
        else
            throw std::runtime_error("cannot make a scratch folder in /tmp");
        const double start = steadySeconds();
        int failures = 0;
        try {
            failures = runRows(rows, settings, summaries);
        } catch (...) {
            fs::remove_all(settings.scratch);
            throw;
        }
        fs::remove_all(settings.scratch);
        std::printf("batch %s: %zu well%s, %d failed, %.2f s\n", settings.manifest.c_str(),
                    rows.size(), rows.size() == 1 ? "" : "s", failures, steadySeconds() - start);
        return failures > 0 ? kExitBadInput : kExitOk;
    });
}

}  // namespace caliper3d::app
