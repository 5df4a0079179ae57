#include "timeline/IntervalLabelEditor.h"

#include "timeline/WaveformView.h"
#include "util/PhoneSet.h"

#include <QComboBox>
#include <QFocusEvent>
#include <QKeyEvent>
#include <QLineEdit>

#include <algorithm>
#include <functional>

namespace lipsync::studio {

namespace {

// Closes the relabel editor on Escape and when it loses focus (not to its own popup).
class EditorFilter : public QObject
{
public:
    EditorFilter(QObject *parent, std::function<void()> close) : QObject(parent), m_close(std::move(close)) {}

protected:
    bool eventFilter(QObject *watched, QEvent *event) override
    {
        if (event->type() == QEvent::KeyPress && static_cast<QKeyEvent *>(event)->key() == Qt::Key_Escape) {
            m_close();
            return true;
        }
        if (event->type() == QEvent::FocusOut
            && static_cast<QFocusEvent *>(event)->reason() != Qt::PopupFocusReason)
            m_close();
        return QObject::eventFilter(watched, event);
    }

private:
    std::function<void()> m_close;
};

} // namespace

IntervalLabelEditor::IntervalLabelEditor(WaveformView *view, QObject *parent) : QObject(parent), m_view(view) {}

void IntervalLabelEditor::open(TierKind kind, int index)
{
    close();
    const Tier &tier = m_view->tier(kind);
    if (index < 0 || index >= int(tier.intervals.size()))
        return;
    const Interval &iv = tier.intervals[size_t(index)];
    const QRect lane = m_view->laneRect(kind == TierKind::Words ? WaveformView::Lane::Words
                                                                     : WaveformView::Lane::Phones);
    const int x0 = int(m_view->xAt(iv.start));
    const int x1 = int(m_view->xAt(iv.end));
    const int w = std::max(x1 - x0, kind == TierKind::Words ? 110 : 80);
    QLineEdit *line = nullptr;
    if (kind == TierKind::Phones) {
        auto *combo = new QComboBox(m_view);
        combo->setEditable(true);
        combo->setInsertPolicy(QComboBox::NoInsert);
        for (std::string_view label : PhoneSet::labels())
            combo->addItem(QString::fromLatin1(label.data(), int(label.size())));
        combo->setCurrentText(QString::fromStdString(iv.label));
        connect(combo, &QComboBox::activated, this, [this] { commit(); });
        line = combo->lineEdit();
        m_editor = combo;
    } else {
        line = new QLineEdit(QString::fromStdString(iv.label), m_view);
        m_editor = line;
    }
    m_editor->setObjectName(QStringLiteral("relabelEditor"));
    m_kind = kind;
    m_index = index;
    auto *filter = new EditorFilter(m_editor, [this] { close(); });
    line->installEventFilter(filter);
    connect(line, &QLineEdit::returnPressed, this, &IntervalLabelEditor::commit);
    connect(line, &QLineEdit::textEdited, this, [line] {
        line->setStyleSheet(QString());
        line->setToolTip(QString());
    });
    const int h = std::max(lane.height() + 4, m_editor->sizeHint().height());
    m_editor->setGeometry(std::clamp(x0, 0, std::max(0, m_view->width() - w)), lane.center().y() - h / 2, w, h);
    m_editor->show();
    line->selectAll();
    m_editor->setFocus(Qt::OtherFocusReason);
}

void IntervalLabelEditor::commit()
{
    if (!m_editor || m_closing)
        return;
    auto *combo = qobject_cast<QComboBox *>(m_editor.data());
    QLineEdit *line = combo ? combo->lineEdit() : qobject_cast<QLineEdit *>(m_editor.data());
    const std::string label = tieredit::validLabel(m_kind, line->text());
    if (label.empty()) {
        line->setStyleSheet(QStringLiteral("background: #7f1d1d; color: white;"));
        line->setToolTip(m_kind == TierKind::Phones ? tr("Not one of the 41 phones (ARPAbet, sil, br)")
                                                          : tr("Enter one word"));
        return;
    }
    const TierKind kind = m_kind;
    const int index = m_index;
    close();
    emit labelChosen(kind, index, label);
}

void IntervalLabelEditor::close()
{
    if (!m_editor || m_closing)
        return;
    m_closing = true;
    QWidget *editor = m_editor;
    m_editor = nullptr;
    editor->hide();
    editor->deleteLater();
    m_closing = false;
}

} // namespace lipsync::studio
