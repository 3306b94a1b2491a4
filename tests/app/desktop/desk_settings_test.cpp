#include "app/desktop/desk_settings.h"

#include <QDockWidget>
#include <QMainWindow>
#include <QSettings>
#include <QStringList>

#include <gtest/gtest.h>

#include "desk_test_support.h"

using namespace caliper3d;

namespace {
void clearRecent(app::DeskSettings& settings) {
    for (const auto& r : settings.recentFiles()) settings.removeRecent(r.path);
}
}  // namespace

TEST(DeskSettingsTest, WritesIntoTheScratchFolderNotTheUsers) {
    test::useScratchSettings();
    app::DeskSettings settings;
    EXPECT_TRUE(settings.fileName().startsWith(test::scratchSettingsFolder()))
        << settings.fileName().toStdString();
}

TEST(DeskSettingsTest, RecentFilesRoundTripMostRecentFirstWithTheirOptions) {
    test::useScratchSettings();
    {
        app::DeskSettings settings;
        clearRecent(settings);
        settings.addRecent({"/logs/a.las", {{"bit-size", "156mm"}, {"wellhead", "1,2,3"}}});
        settings.addRecent({"/logs/b.txt", {{"arms", "8"}}});
        settings.setLastFolder("/logs");
    }
    app::DeskSettings again;  // a new run reads what the last one wrote
    const auto recent = again.recentFiles();
    ASSERT_EQ(recent.size(), 2);
    EXPECT_EQ(recent[0].path, "/logs/b.txt");
    EXPECT_EQ(recent[0].options, (app::OptionTexts{{"arms", "8"}}));
    EXPECT_EQ(recent[1].path, "/logs/a.las");
    EXPECT_EQ(recent[1].options, (app::OptionTexts{{"bit-size", "156mm"}, {"wellhead", "1,2,3"}}));
    EXPECT_EQ(again.lastFolder(), "/logs");
}

TEST(DeskSettingsTest, RecentFilesOfAnEarlierVersionLoadTheirOptions) {
    test::useScratchSettings();
    {
        app::DeskSettings settings;
        clearRecent(settings);
    }
    {
        // What an earlier version wrote: the command line that opened each file.
        QSettings earlier("caliper3d", "caliper3d");
        earlier.beginWriteArray("recentFiles", 2);
        earlier.setArrayIndex(0);
        earlier.setValue("path", "/logs/old.las");
        earlier.setValue("arguments", QStringList{"--arms", "6", "--bit-size", "6.5in",
                                                  "--wellhead", "1,2,3", "--", "/logs/old.las"});
        earlier.setArrayIndex(1);
        earlier.setValue("path", "/logs/odd.las");
        earlier.setValue("arguments", QStringList{"/logs/odd.las"});
        earlier.endArray();
    }
    app::DeskSettings settings;
    const auto recent = settings.recentFiles();
    ASSERT_EQ(recent.size(), 2);
    EXPECT_EQ(recent[0].options,
              (app::OptionTexts{{"arms", "6"}, {"bit-size", "6.5in"}, {"wellhead", "1,2,3"}}));
    EXPECT_TRUE(recent[1].options.empty());
    clearRecent(settings);
}

TEST(DeskSettingsTest, KeepsTenOnePerPathAndRemoves) {
    test::useScratchSettings();
    app::DeskSettings settings;
    clearRecent(settings);
    for (int i = 0; i < 14; ++i) settings.addRecent({QString("/logs/%1.las").arg(i), {}});
    settings.addRecent({"/logs/7.las", {{"arms", "4"}}});
    auto recent = settings.recentFiles();
    ASSERT_EQ(recent.size(), app::DeskSettings::kMaxRecent);
    EXPECT_EQ(recent[0].path, "/logs/7.las");
    EXPECT_EQ(recent[0].options.at("arms"), "4");
    EXPECT_EQ(recent[1].path, "/logs/13.las");
    EXPECT_EQ(recent.back().path, "/logs/4.las");  // 7, then 13..4 but 7: 3 and older gone
    settings.removeRecent("/logs/13.las");
    recent = settings.recentFiles();
    EXPECT_EQ(recent.size(), app::DeskSettings::kMaxRecent - 1);
    EXPECT_EQ(recent[1].path, "/logs/12.las");
}

TEST(DeskSettingsTest, WindowLayoutRoundTripsWithTheDocks) {
    CALIPER3D_REQUIRE_GUI();
    auto makeWindow = [] {
        auto window = std::make_unique<QMainWindow>();
        window->setCentralWidget(new QWidget);
        auto* dock = new QDockWidget("Log", window.get());
        dock->setObjectName("logDock");
        window->addDockWidget(Qt::LeftDockWidgetArea, dock);
        return window;
    };
    {
        auto window = makeWindow();
        window->resize(700, 500);
        window->show();
        auto* dock = window->findChild<QDockWidget*>("logDock");
        window->addDockWidget(Qt::BottomDockWidgetArea, dock);
        dock->hide();
        app::DeskSettings settings;
        settings.saveLayout(*window);
    }
    auto window = makeWindow();
    window->show();
    app::DeskSettings settings;
    ASSERT_TRUE(settings.restoreLayout(*window));
    auto* dock = window->findChild<QDockWidget*>("logDock");
    EXPECT_EQ(window->dockWidgetArea(dock), Qt::BottomDockWidgetArea);
    EXPECT_TRUE(dock->isHidden());
    EXPECT_EQ(window->size(), QSize(700, 500));
}
