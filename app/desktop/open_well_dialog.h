#pragma once

#include <optional>
#include <vector>

#include <QDialog>

#include "app/desktop/open_choices.h"
#include "io/log_info.h"

class QComboBox;
class QDialogButtonBox;
class QLabel;
class QLineEdit;
class QSpinBox;
class QTableWidget;
class QTimer;

namespace caliper3d::app {

// File > Open and Add: what `caliper3d info` detects in a file (format, rows, depth range,
// arms, each curve and its role, units, the log's bit size, the well's name), and the
// options a user may set for it: a field for each option of the table that names one
// (app/well_option_table.h: curve roles, units, bit size, survey, wellhead), which map to
// the well's load options through openRequestFrom. The file is described again with the
// options as they change, so a wrong curve name or unit shows here, with OK disabled, and not
// as a failed load. A file that cannot be read shows its file, line and reason.
class OpenWellDialog : public QDialog {
    Q_OBJECT

public:
    // `look`: the exaggeration and colouring the window draws with (all it takes from it).
    // `initial`: choices to start from (a recent file's), else the file's defaults.
    OpenWellDialog(const QString& path, const LoadOptions& look, QWidget* parent = nullptr,
                   const std::optional<OpenChoices>& initial = std::nullopt);

    OpenChoices choices() const;
    // The well and its options as chosen; valid when OK is enabled.
    const ParsedWells& request() const { return m_request; }
    // What the file holds, read with the options chosen (null when it could not be read).
    const io::LogInfo* info() const { return m_info ? &*m_info : nullptr; }
    // Why OK is disabled (empty when it is enabled).
    QString errorText() const;
    bool acceptable() const;

    // Describes the file again with the options as they are now (done by a timer as they
    // are edited).
    void describe();

private:
    // One option's widget: a line edit, a combo box (Choice) or a spin box (Count).
    struct Field {
        const WellOption* option = nullptr;
        QLineEdit* edit = nullptr;
        QComboBox* box = nullptr;
        QSpinBox* spin = nullptr;
        QWidget* widget() const;
        QString text() const;
        void setText(const QString& text) const;
    };

    void buildForm();
    void buildDetected();
    void showInfo();
    void showError(const QString& message);
    void browse(const Field& field);

    QString m_path;
    LoadOptions m_look;
    ParsedWells m_request;
    std::optional<io::LogInfo> m_info;
    QLabel* m_summary = nullptr;
    QTableWidget* m_curves = nullptr;
    QLabel* m_error = nullptr;
    std::vector<Field> m_fields;
    OptionTexts m_unshown;  // options of the initial choices without a field here, kept
    QDialogButtonBox* m_buttons = nullptr;
    QTimer* m_again = nullptr;  // describes the file again once the edits pause
};

}  // namespace caliper3d::app
