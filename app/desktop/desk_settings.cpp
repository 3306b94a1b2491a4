#include "app/desktop/desk_settings.h"

#include <algorithm>

#include <QMainWindow>
#include <QSettings>
#include <QStringList>
#include <QVariantMap>

namespace caliper3d::app {

namespace {
const char* const kRecent = "recentFiles";
const char* const kPath = "path";
const char* const kOptions = "options";
// Earlier versions kept the command line that opened the file: "--NAME VALUE ... -- FILE".
const char* const kArguments = "arguments";
const char* const kLastFolder = "lastFolder";
const char* const kGeometry = "window/geometry";
const char* const kState = "window/state";
// Bumped when the docks change so much that an old layout should not be restored.
constexpr int kLayoutVersion = 1;

OptionTexts fromMap(const QVariantMap& map) {
    OptionTexts out;
    for (auto it = map.begin(); it != map.end(); ++it)
        out[it.key().toStdString()] = it.value().toString().toStdString();
    return out;
}

QVariantMap toMap(const OptionTexts& options) {
    QVariantMap out;
    for (const auto& [name, text] : options)
        out.insert(QString::fromStdString(name), QString::fromStdString(text));
    return out;
}

// An earlier version's arguments as texts: the "--NAME VALUE" pairs before "--". A name the
// table does not know is kept, so that opening it fails and the Open dialog is shown instead.
OptionTexts fromArguments(const QStringList& arguments) {
    OptionTexts out;
    for (int i = 0;
         i + 1 < arguments.size() && arguments[i].startsWith("--") && arguments[i] != "--"; i += 2)
        out[arguments[i].mid(2).toStdString()] = arguments[i + 1].toStdString();
    return out;
}
}  // namespace

DeskSettings::DeskSettings() : m_settings(std::make_unique<QSettings>("caliper3d", "caliper3d")) {}

DeskSettings::~DeskSettings() = default;

QList<DeskSettings::Recent> DeskSettings::recentFiles() const {
    QList<Recent> out;
    const int size = m_settings->beginReadArray(kRecent);
    for (int i = 0; i < size && out.size() < kMaxRecent; ++i) {
        m_settings->setArrayIndex(i);
        Recent recent{m_settings->value(kPath).toString(), {}};
        recent.options = m_settings->contains(kOptions)
                             ? fromMap(m_settings->value(kOptions).toMap())
                             : fromArguments(m_settings->value(kArguments).toStringList());
        if (!recent.path.isEmpty()) out << recent;
    }
    m_settings->endArray();
    return out;
}

void DeskSettings::writeRecent(const QList<Recent>& list) {
    m_settings->remove(kRecent);
    m_settings->beginWriteArray(kRecent, list.size());
    for (int i = 0; i < list.size(); ++i) {
        m_settings->setArrayIndex(i);
        m_settings->setValue(kPath, list[i].path);
        m_settings->setValue(kOptions, toMap(list[i].options));
    }
    m_settings->endArray();
    m_settings->sync();
}

void DeskSettings::addRecent(const Recent& recent) {
    QList<Recent> list = recentFiles();
    list.erase(std::remove_if(list.begin(), list.end(),
                              [&](const Recent& r) { return r.path == recent.path; }),
               list.end());
    list.prepend(recent);
    while (list.size() > kMaxRecent) list.removeLast();
    writeRecent(list);
}

void DeskSettings::removeRecent(const QString& path) {
    QList<Recent> list = recentFiles();
    list.erase(
        std::remove_if(list.begin(), list.end(), [&](const Recent& r) { return r.path == path; }),
        list.end());
    writeRecent(list);
}

QString DeskSettings::lastFolder() const {
    return m_settings->value(kLastFolder).toString();
}

void DeskSettings::setLastFolder(const QString& folder) {
    m_settings->setValue(kLastFolder, folder);
    m_settings->sync();
}

void DeskSettings::saveLayout(const QMainWindow& window) {
    m_settings->setValue(kGeometry, window.saveGeometry());
    m_settings->setValue(kState, window.saveState(kLayoutVersion));
    m_settings->sync();
}

bool DeskSettings::restoreLayout(QMainWindow& window) const {
    const QByteArray geometry = m_settings->value(kGeometry).toByteArray();
    const QByteArray state = m_settings->value(kState).toByteArray();
    if (geometry.isEmpty() && state.isEmpty()) return false;
    if (!geometry.isEmpty()) window.restoreGeometry(geometry);
    if (!state.isEmpty()) window.restoreState(state, kLayoutVersion);
    return true;
}

QString DeskSettings::fileName() const {
    return m_settings->fileName();
}

}  // namespace caliper3d::app
