#include "plots/VtkWidget.h"

#include <QMouseEvent>
#include <QOpenGLContext>
#include <QOpenGLExtraFunctions>
#include <QWheelEvent>

#include <vtkCallbackCommand.h>
#include <vtkCommand.h>
#include <vtkGenericOpenGLRenderWindow.h>
#include <vtkGenericRenderWindowInteractor.h>
#include <vtkNew.h>
#include <vtkOpenGLFramebufferObject.h>
#include <vtkSmartPointer.h>

namespace lipsync::studio {

struct VtkWidget::Impl
{
    vtkNew<vtkGenericOpenGLRenderWindow> window;
    vtkNew<vtkGenericRenderWindowInteractor> interactor;
    vtkNew<vtkCallbackCommand> observer;
    VtkWidget *widget = nullptr;
    bool painting = false;
};


// One callback for every event VTK sends about "its" window; clientData is the Impl.
void VtkWidget::onVtkEvent(vtkObject *, unsigned long event, void *clientData, void *callData)
{
    auto *impl = static_cast<Impl *>(clientData);
    VtkWidget *widget = impl->widget;
    QOpenGLContext *context = widget->context();
    switch (event) {
    case vtkCommand::WindowMakeCurrentEvent:
        // Not QOpenGLWidget::makeCurrent(): that rebinds Qt's framebuffer behind VTK's cached
        // GL state and the widget stays black.
        if (context)
            context->makeCurrent(context->surface());
        break;
    case vtkCommand::WindowIsCurrentEvent:
        *static_cast<bool *>(callData) = context && QOpenGLContext::currentContext() == context;
        break;
    case vtkCommand::WindowFrameEvent:
    case vtkCommand::RenderEvent:
        // Render() inside paintGL ends with a frame event: asking for another paint then would
        // repaint forever.
        if (!impl->painting)
            widget->update();
        break;
    default:
        break;
    }
}

VtkWidget::VtkWidget(QWidget *parent) : QOpenGLWidget(parent), d(std::make_unique<Impl>())
{
    d->window->SetInteractor(d->interactor);
    d->interactor->SetRenderWindow(d->window);
    d->interactor->EnableRenderOff();
    d->window->SetReadyForRendering(false);
    d->window->SetOwnContext(0);
    d->window->SetUseOffScreenBuffers(false);
    d->window->SetFrameBlitModeToNoBlit();
    d->window->SetForceMaximumHardwareLineWidth(1);

    d->widget = this;
    d->observer->SetCallback(&VtkWidget::onVtkEvent);
    d->observer->SetClientData(d.get());
    d->window->AddObserver(vtkCommand::WindowMakeCurrentEvent, d->observer);
    d->window->AddObserver(vtkCommand::WindowIsCurrentEvent, d->observer);
    d->window->AddObserver(vtkCommand::WindowFrameEvent, d->observer);
    d->interactor->AddObserver(vtkCommand::RenderEvent, d->observer);
    setMouseTracking(false);
    setFocusPolicy(Qt::StrongFocus);
}

VtkWidget::~VtkWidget()
{
    // Remove the observers first: VTK's Finalize() must not call back into a half-destroyed widget.
    d->window->RemoveObserver(d->observer);
    d->interactor->RemoveObserver(d->observer);
    if (context())
        disconnect(context(), nullptr, this, nullptr);
    if (context() && context()->isValid()) {
        makeCurrent();
        d->window->Finalize();
        doneCurrent();
    }
}

vtkGenericOpenGLRenderWindow *VtkWidget::renderWindow() const
{
    return d->window;
}

vtkGenericRenderWindowInteractor *VtkWidget::interactor() const
{
    return d->interactor;
}

void VtkWidget::finalizeVtk()
{
    // The context is going away (widget reparented or destroyed): free VTK's GL resources while
    // it can still be made current.
    if (context()) {
        context()->makeCurrent(context()->surface());
        d->window->Finalize();
        d->window->SetReadyForRendering(false);
    }
}

void VtkWidget::initializeGL()
{
    d->window->SetReadyForRendering(true);
    d->window->InitializeFromCurrentContext();
    d->window->SetMapped(1);
    d->interactor->Initialize();
    connect(context(), &QOpenGLContext::aboutToBeDestroyed, this, &VtkWidget::finalizeVtk,
            Qt::UniqueConnection);
}

void VtkWidget::resizeGL(int w, int h)
{
    const qreal dpr = devicePixelRatioF();
    const int pw = int(w * dpr);
    const int ph = int(h * dpr);
    d->window->SetSize(pw, ph);
    d->interactor->UpdateSize(pw, ph);
    d->window->SetDPI(int(72 * dpr));
}

void VtkWidget::paintGL()
{
    if (d->painting || !d->window->GetReadyForRendering())
        return;
    d->painting = true;
    d->window->Render();

    // VTK rendered into its own framebuffer; copy it into the one Qt composes the widget from.
    auto *f = context()->extraFunctions();
    f->glBindFramebuffer(GL_DRAW_FRAMEBUFFER, defaultFramebufferObject());
    const GLenum attachment = GL_COLOR_ATTACHMENT0;
    f->glDrawBuffers(1, &attachment);
    int source[2] = {0, 0};
    d->window->GetRenderFramebuffer()->GetLastSize(source);
    const qreal dpr = devicePixelRatioF();
    const int tw = int(width() * dpr);
    const int th = int(height() * dpr);
    d->window->BlitDisplayFramebuffer(0, 0, 0, source[0], source[1], 0, 0, tw, th,
                                      GL_COLOR_BUFFER_BIT, GL_LINEAR);
    // Qt composes the widget with alpha: force it opaque or the chart looks washed out.
    f->glColorMask(GL_FALSE, GL_FALSE, GL_FALSE, GL_TRUE);
    f->glClearColor(0, 0, 0, 1);
    f->glClear(GL_COLOR_BUFFER_BIT);
    f->glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
    d->painting = false;
}

void VtkWidget::forwardMouse(QMouseEvent *event, unsigned long vtkEvent)
{
    const qreal dpr = devicePixelRatioF();
    const QPointF p = event->position();
    d->interactor->SetEventInformationFlipY(int(p.x() * dpr), int(p.y() * dpr),
                                            event->modifiers() & Qt::ControlModifier ? 1 : 0,
                                            event->modifiers() & Qt::ShiftModifier ? 1 : 0);
    d->interactor->InvokeEvent(vtkEvent, event);
    update();
}

void VtkWidget::mousePressEvent(QMouseEvent *event)
{
    switch (event->button()) {
    case Qt::LeftButton: forwardMouse(event, vtkCommand::LeftButtonPressEvent); break;
    case Qt::RightButton: forwardMouse(event, vtkCommand::RightButtonPressEvent); break;
    case Qt::MiddleButton: forwardMouse(event, vtkCommand::MiddleButtonPressEvent); break;
    default: break;
    }
}

void VtkWidget::mouseReleaseEvent(QMouseEvent *event)
{
    switch (event->button()) {
    case Qt::LeftButton: forwardMouse(event, vtkCommand::LeftButtonReleaseEvent); break;
    case Qt::RightButton: forwardMouse(event, vtkCommand::RightButtonReleaseEvent); break;
    case Qt::MiddleButton: forwardMouse(event, vtkCommand::MiddleButtonReleaseEvent); break;
    default: break;
    }
}

void VtkWidget::mouseMoveEvent(QMouseEvent *event)
{
    forwardMouse(event, vtkCommand::MouseMoveEvent);
}

void VtkWidget::wheelEvent(QWheelEvent *event)
{
    const qreal dpr = devicePixelRatioF();
    const QPointF p = event->position();
    d->interactor->SetEventInformationFlipY(int(p.x() * dpr), int(p.y() * dpr));
    d->interactor->InvokeEvent(event->angleDelta().y() > 0 ? vtkCommand::MouseWheelForwardEvent
                                                           : vtkCommand::MouseWheelBackwardEvent,
                               event);
    update();
}

} // namespace lipsync::studio
