#pragma once

#include <functional>
#include <string>
#include <vector>

#include <QCommandLineParser>
#include <QStringList>

namespace caliper3d::app {

// QCommandLineParser set up for one verb ("caliper3d VERB"), with --help.
class VerbParser {
public:
    VerbParser(const char* verb, const char* positionalSyntax, const char* description);
    QCommandLineParser& parser() { return m_parser; }

    // Parses; throws UsageError on unknown options or when fewer than
    // `minPositional` positional arguments are given. Returns false when
    // --help was asked for (and printed).
    bool parse(const QStringList& args, int minPositional);
    std::vector<std::string> positional() const;
    // The verb's --help text: usage line, description, every option.
    std::string helpText() const;
    std::string value(const char* name) const { return m_parser.value(name).toStdString(); }
    bool isSet(const char* name) const { return m_parser.isSet(name); }

private:
    std::string m_verb;
    QCommandLineParser m_parser;
};

// Runs a verb's body and turns what it throws into the exit status:
// UsageError -> 2, any other error -> 1, each reported on stderr.
int guardedVerb(const char* verb, const std::function<int()>& body);

}  // namespace caliper3d::app
