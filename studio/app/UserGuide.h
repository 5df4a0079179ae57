#pragma once
// Help ▸ User Guide: the README (what the studio is, its workflows, the CLI) and the docs it
// links to (models, pipeline, formats, performance), built into the studio as resources so that
// they are there wherever it is installed, shown as formatted text with working links.
#include <QDialog>

class QTextBrowser;

namespace lipsync::studio {

class UserGuide : public QDialog
{
    Q_OBJECT
public:
    explicit UserGuide(QWidget *parent = nullptr);

    QTextBrowser *browser() const { return m_browser; }
    // The README's address among the resources.
    static QUrl home();

private:
    QTextBrowser *m_browser;
};

} // namespace lipsync::studio
