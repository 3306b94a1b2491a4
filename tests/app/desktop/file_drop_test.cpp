#include "app/desktop/file_drop.h"

#include <fstream>

#include <gtest/gtest.h>
#include <QMimeData>
#include <QUrl>

#include "test_support.h"

using namespace caliper3d;

TEST(FileDropTest, APlainDropOpensTheFirstFileAndAModifierAddsThemAll) {
    const QStringList paths{"/a.las", "/b.las", "/c.txt"};
    bool add = true;
    EXPECT_EQ(app::FileDrop::filesToOpen(paths, Qt::NoModifier, add), QStringList{"/a.las"});
    EXPECT_FALSE(add);
    EXPECT_EQ(app::FileDrop::filesToOpen(paths, Qt::ControlModifier, add), paths);
    EXPECT_TRUE(add);
    EXPECT_EQ(app::FileDrop::filesToOpen(paths, Qt::ShiftModifier, add), paths);
    EXPECT_TRUE(add);
}

TEST(FileDropTest, OnlyLocalFilesThatExistAreTaken) {
    const auto file = test::scratch("drop.las");
    std::ofstream(file) << "x\n";
    QMimeData data;
    data.setUrls({QUrl::fromLocalFile(QString::fromStdString(file.string())),
                  QUrl("https://example.com/w.las"),
                  QUrl::fromLocalFile(QString::fromStdString(test::scratch("no-such").string())),
                  QUrl::fromLocalFile(QString::fromStdString(file.parent_path().string()))});
    EXPECT_EQ(app::FileDrop::localFiles(data), QStringList{QString::fromStdString(file.string())});
    QMimeData text;
    text.setText("/a.las");
    EXPECT_TRUE(app::FileDrop::localFiles(text).isEmpty());
}
