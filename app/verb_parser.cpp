#include "app/verb_parser.h"

#include <cstdio>
#include <memory>

#include <QCoreApplication>

#include "app/input_options.h"

namespace caliper3d::app {

VerbParser::VerbParser(const char* verb, const char* positionalSyntax, const char* description)
    : m_verb(verb) {
    m_parser.setApplicationDescription(description);
    m_parser.addHelpOption();
    m_parser.addPositionalArgument("args", "", positionalSyntax);
}

bool VerbParser::parse(const QStringList& args, int minPositional) {
    QStringList full = args;
    full.prepend(QString("caliper3d ") + QString::fromStdString(m_verb));
    if (!m_parser.parse(full))
        throw UsageError("caliper3d " + m_verb + ": " + m_parser.errorText().toStdString());
    if (m_parser.isSet("help") || m_parser.isSet("help-all")) {
        std::fputs(helpText().c_str(), stdout);
        return false;
    }
    if (m_parser.positionalArguments().size() < minPositional)
        throw UsageError("caliper3d " + m_verb + ": missing arguments; see 'caliper3d " + m_verb +
                         " --help'");
    return true;
}

std::string VerbParser::helpText() const {
    // QCommandLineParser takes the program name for its "Usage:" line from the
    // application object, and crashes without one; the verbs that need no window
    // run without one, so a short-lived one is made here, named "caliper3d VERB".
    static int argc = 1;
    static std::string name;
    static char* argv[] = {nullptr, nullptr};
    std::unique_ptr<QCoreApplication> application;
    if (!QCoreApplication::instance()) {
        name = "caliper3d " + m_verb;
        argv[0] = name.data();
        application = std::make_unique<QCoreApplication>(argc, argv);
    }
    QString text = m_parser.helpText();
    if (application) return text.toStdString();
    // Under an existing application (the window), name the verb all the same.
    const QString program = QCoreApplication::arguments().value(0);
    if (!program.isEmpty() && text.startsWith("Usage: " + program))
        text.replace(0, 7 + program.size(), QString::fromStdString("Usage: caliper3d " + m_verb));
    return text.toStdString();
}

std::vector<std::string> VerbParser::positional() const {
    std::vector<std::string> out;
    for (const QString& s : m_parser.positionalArguments()) out.push_back(s.toStdString());
    return out;
}

int guardedVerb(const char* verb, const std::function<int()>& body) {
    try {
        return body();
    } catch (const UsageError& e) {
        std::fprintf(stderr, "%s\n", e.what());
        return 2;
    } catch (const std::exception& e) {
        std::fprintf(stderr, "caliper3d %s: %s\n", verb, e.what());
        return 1;
    }
}

}  // namespace caliper3d::app
