// Python's headers name a struct member "slots", which Qt defines as a macro: they come first.
#include "vtkPython.h"

#include "pqStylizeFigureActions.h"

#include "pqActiveObjects.h"
#include "pqCoreUtilities.h"
#include "pqFileDialog.h"
#include "pqView.h"
#include "vtkPythonInterpreter.h"
#include "vtkSMProxy.h"
#include "vtkSmartPyObject.h"

#include <QApplication>
#include <QCheckBox>
#include <QDialog>
#include <QDialogButtonBox>
#include <QDoubleSpinBox>
#include <QFormLayout>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QMainWindow>
#include <QMessageBox>
#include <QPushButton>
#include <QSpinBox>
#include <QStatusBar>

namespace
{
// What ParaView's Python shell runs before the first command, for a GUI where nothing has run
// Python yet: the plugin's Python modules (stylize_paraview) are importable only through the
// finder paraview.servermanager installs, which also attaches to the GUI's session.
// (paraview.fromGUI before that first import: no progress printing to the terminal.)
const char* const PrepareParaViewPython = "import sys\n"
                                          "if 'paraview.servermanager' not in sys.modules:\n"
                                          "    import paraview\n"
                                          "    paraview.fromGUI = True\n"
                                          "    import paraview.simple\n";

// Calls stylize_paraview.FUNCTION(argument), or FUNCTION() for a null `argument`, in ParaView's
// Python and returns the str it returns; on a Python failure (the module not importable, say)
// returns "" and sets `error`.
QString CallPython(const char* function, const QString& argument, QString& error)
{
  vtkPythonInterpreter::Initialize();
  vtkPythonScopeGilEnsurer gil;
  vtkSmartPyObject module;
  if (PyRun_SimpleString(PrepareParaViewPython) == 0)
  {
    module.TakeReference(PyImport_ImportModule("stylize_paraview"));
  }
  else
  {
    PyErr_SetString(PyExc_ImportError, "ParaView's Python (paraview.simple) did not import");
  }
  vtkSmartPyObject result;
  if (module)
  {
    const QByteArray utf8 = argument.toUtf8();
    result.TakeReference(argument.isNull()
        ? PyObject_CallMethod(module, function, nullptr)
        : PyObject_CallMethod(module, function, "s", utf8.constData()));
  }
  const char* text = result && PyUnicode_Check(result) ? PyUnicode_AsUTF8(result) : nullptr;
  if (!text)
  {
    PyObject *type = nullptr, *value = nullptr, *traceback = nullptr;
    PyErr_Fetch(&type, &value, &traceback);
    vtkSmartPyObject message(value ? PyObject_Str(value) : nullptr);
    const char* line = message ? PyUnicode_AsUTF8(message) : nullptr;
    error = QString("stylize_paraview.%1 failed: %2")
              .arg(function)
              .arg(line ? line : "no result from Python");
    Py_XDECREF(type);
    Py_XDECREF(value);
    Py_XDECREF(traceback);
    PyErr_Clear();
    return QString();
  }
  return QString::fromUtf8(text);
}

// Shows a refusal's line in a warning box (named StylizeMessage, for QtTesting).
void ShowRefusal(const QString& error)
{
  QMessageBox box(QMessageBox::Warning, QObject::tr("VTK Stylize"), error, QMessageBox::Ok,
    pqCoreUtilities::mainWidget());
  box.setObjectName("StylizeMessage");
  box.exec();
}

// Runs stylize_paraview.FUNCTION(**arguments) on the active view (through _gui_call) with a wait
// cursor; shows the failure in a message box, or the written files in the status bar.
void RunStylizeCall(const QString& function, const QJsonObject& arguments)
{
  QJsonObject request;
  request["function"] = function;
  request["arguments"] = arguments;
  QString error;
  QApplication::setOverrideCursor(Qt::WaitCursor);
  const QString reply = CallPython(
    "_gui_call", QString::fromUtf8(QJsonDocument(request).toJson(QJsonDocument::Compact)), error);
  QApplication::restoreOverrideCursor();
  const QJsonObject result = QJsonDocument::fromJson(reply.toUtf8()).object();
  if (error.isEmpty())
  {
    error = result.value("error").toString();
  }
  QWidget* main = pqCoreUtilities::mainWidget();
  if (!error.isEmpty())
  {
    ShowRefusal(error);
    return;
  }
  const QJsonArray written = result.value("written").toArray();
  if (auto* window = qobject_cast<QMainWindow*>(main))
  {
    window->statusBar()->showMessage(
      QObject::tr("Wrote %1 file(s), the last %2")
        .arg(written.size())
        .arg(written.isEmpty() ? QString() : written.last().toString()),
      10000);
  }
}

// Asks for the file to write on the active server; "" when the user cancels.
QString AskFile(const QString& title, const QString& filters, const QString& name)
{
  pqFileDialog dialog(pqActiveObjects::instance().activeServer(), pqCoreUtilities::mainWidget(),
    title, QString(), filters);
  dialog.setObjectName(name);
  dialog.setFileMode(pqFileDialog::AnyFile);
  if (dialog.exec() != QDialog::Accepted || dialog.getSelectedFiles().isEmpty())
  {
    return QString();
  }
  return dialog.getSelectedFiles().first();
}

// One field of the orbit dialog for an entry of stylize_paraview.ORBIT_OPTIONS: a check box, a
// spin box or a decimal spin box by the default's type; named by its keyword (for QtTesting).
QWidget* OrbitField(const QJsonObject& option, QWidget* parent)
{
  const QJsonValue value = option.value("default");
  const QString type = option.value("type").toString();
  QWidget* field = nullptr;
  if (type == "bool")
  {
    auto* box = new QCheckBox(parent);
    box->setChecked(value.toBool());
    field = box;
  }
  else if (type == "int")
  {
    auto* box = new QSpinBox(parent);
    box->setRange(option.value("minimum").toInt(), option.value("maximum").toInt());
    box->setValue(value.toInt());
    field = box;
  }
  else // "float", the only other type _gui_orbit_options gives
  {
    auto* box = new QDoubleSpinBox(parent);
    box->setDecimals(2);
    box->setRange(option.value("minimum").toDouble(), option.value("maximum").toDouble());
    box->setValue(value.toDouble());
    field = box;
  }
  field->setObjectName(option.value("name").toString());
  field->setToolTip(option.value("help").toString());
  return field;
}

// The value a field of OrbitField holds, as JSON.
QJsonValue OrbitFieldValue(QWidget* field)
{
  if (auto* check = qobject_cast<QCheckBox*>(field))
  {
    return check->isChecked();
  }
  if (auto* spin = qobject_cast<QSpinBox*>(field))
  {
    return spin->value();
  }
  return qobject_cast<QDoubleSpinBox*>(field)->value();
}
} // namespace

//------------------------------------------------------------------------------
pqStylizeFigureActions::pqStylizeFigureActions(QObject* parent)
  : QActionGroup(parent)
{
  this->setExclusive(false);
  this->FigureAction = this->addAction(tr("Export Stylized Figure..."));
  this->FigureAction->setObjectName("actionStylizeExportFigure");
  this->FigureAction->setStatusTip(
    tr("Write the active VTK Stylize view as a vector figure (SVG or PDF)"));
  this->OrbitAction = this->addAction(tr("Save Stylized Orbit..."));
  this->OrbitAction->setObjectName("actionStylizeSaveOrbit");
  this->OrbitAction->setStatusTip(
    tr("Orbit the camera of the active VTK Stylize view and save the frames (PNG, GIF or MP4)"));
  QObject::connect(
    this->FigureAction, &QAction::triggered, this, &pqStylizeFigureActions::exportFigure);
  QObject::connect(
    this->OrbitAction, &QAction::triggered, this, &pqStylizeFigureActions::saveOrbit);
  QObject::connect(&pqActiveObjects::instance(), &pqActiveObjects::viewChanged, this,
    &pqStylizeFigureActions::updateEnabled);
  this->updateEnabled();
}

//------------------------------------------------------------------------------
void pqStylizeFigureActions::updateEnabled()
{
  pqView* view = pqActiveObjects::instance().activeView();
  const bool stylized =
    view && view->getProxy() && QString(view->getProxy()->GetXMLName()) == "StylizeView";
  this->FigureAction->setEnabled(stylized);
  this->OrbitAction->setEnabled(stylized);
}

//------------------------------------------------------------------------------
void pqStylizeFigureActions::exportFigure()
{
  const QString file = AskFile(tr("Export Stylized Figure"),
    tr("SVG Figure (*.svg);;PDF Figure (*.pdf)"), "StylizeFigureFileDialog");
  if (!file.isEmpty())
  {
    QJsonObject arguments;
    arguments["filename"] = file;
    RunStylizeCall("SaveStylizedFigure", arguments);
  }
}

//------------------------------------------------------------------------------
void pqStylizeFigureActions::saveOrbit()
{
  QString error;
  const QString options = CallPython("_gui_orbit_options", QString(), error);
  if (!error.isEmpty())
  {
    ShowRefusal(error);
    return;
  }
  const QString file = AskFile(tr("Save Stylized Orbit"),
    tr("GIF Animation (*.gif);;MP4 Video (*.mp4);;PNG Frames (*.png)"), "StylizeOrbitFileDialog");
  if (file.isEmpty())
  {
    return;
  }
  QDialog dialog(pqCoreUtilities::mainWidget());
  dialog.setObjectName("StylizeOrbitDialog");
  dialog.setWindowTitle(tr("Save Stylized Orbit"));
  auto* form = new QFormLayout(&dialog);
  QList<QWidget*> fields;
  for (const QJsonValue& option : QJsonDocument::fromJson(options.toUtf8()).array())
  {
    fields.append(OrbitField(option.toObject(), &dialog));
    form->addRow(option.toObject().value("label").toString(), fields.last());
  }
  auto* buttons = new QDialogButtonBox(QDialogButtonBox::Ok | QDialogButtonBox::Cancel, &dialog);
  buttons->setObjectName("ButtonBox");
  buttons->button(QDialogButtonBox::Ok)->setObjectName("OkButton");
  buttons->button(QDialogButtonBox::Cancel)->setObjectName("CancelButton");
  QObject::connect(buttons, &QDialogButtonBox::accepted, &dialog, &QDialog::accept);
  QObject::connect(buttons, &QDialogButtonBox::rejected, &dialog, &QDialog::reject);
  form->addRow(buttons);
  if (dialog.exec() != QDialog::Accepted)
  {
    return;
  }
  QJsonObject arguments;
  arguments["output"] = file;
  for (QWidget* field : fields)
  {
    arguments[field->objectName()] = OrbitFieldValue(field);
  }
  RunStylizeCall("SaveStylizedOrbit", arguments);
}
