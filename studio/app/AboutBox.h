#pragma once
// Help → About: version, the paper the studio implements, and the data attribution.
#include <QCoreApplication>

class QWidget;

namespace lipsync::studio {

class AboutBox
{
    Q_DECLARE_TR_FUNCTIONS(AboutBox)

public:
    static QString text();
    static void show(QWidget *parent);
};

} // namespace lipsync::studio
