#include "app/AboutBox.h"

#include <QMessageBox>

namespace lipsync::studio {

QString AboutBox::text()
{
    return tr("<h3>LipSync Studio %1</h3>"
              "<p>Realistic lip movement from speech, after G. Englebienne, T. F. Cootes and M. Rattray, "
              "<i>A Probabilistic Model for Generating Realistic Lip Movements from Speech</i>, "
              "Advances in Neural Information Processing Systems 20 (NIPS 2007).</p>"
              "<p>Demo clips: GRID audio-visual corpus (Cooke, Barker, Cunningham, Shao, JASA 120(5), 2006), "
              "speaker s1, CC BY 4.0; YuNet face detector (MIT).</p>")
        .arg(QStringLiteral(LIPSYNC_VERSION));
}

void AboutBox::show(QWidget *parent)
{
    QMessageBox::about(parent, tr("About LipSync Studio"), text());
}

} // namespace lipsync::studio
