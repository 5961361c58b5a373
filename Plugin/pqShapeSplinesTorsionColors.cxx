#include "pqShapeSplinesTorsionColors.h"

#include "ArrayNames.h"

#include "pqApplicationCore.h"
#include "pqDataRepresentation.h"
#include "pqServerManagerModel.h"
#include "vtkDataObject.h"
#include "vtkPVArrayInformation.h"
#include "vtkPVDataInformation.h"
#include "vtkPVDataSetAttributesInformation.h"
#include "vtkSMPVRepresentationProxy.h"
#include "vtkSMPropertyHelper.h"
#include "vtkSMTransferFunctionManager.h"
#include "vtkSMTransferFunctionProxy.h"

#include <QSet>
#include <QTimer>

#include <algorithm>
#include <cstring>
#include <optional>

namespace
{
/// Whether the representation colours by the point array Torsion.
bool ColorsByTorsion(pqDataRepresentation* representation)
{
  vtkSMProxy* proxy = representation->getProxy();
  if (!vtkSMPVRepresentationProxy::GetUsingScalarColoring(proxy))
  {
    return false;
  }
  vtkSMPropertyHelper colorArray(proxy, "ColorArrayName", /*quiet=*/true);
  const char* name = colorArray.GetInputArrayNameToProcess();
  return colorArray.GetInputArrayAssociation() == vtkDataObject::FIELD_ASSOCIATION_POINTS &&
    name != nullptr && std::strcmp(name, shapesplines::names::Torsion) == 0;
}

/// m of the input's field data TorsionColorRange (-m, m), if it has one. For
/// composite data the information merges the blocks' ranges: the largest m.
std::optional<double> RobustTorsion(pqDataRepresentation* representation)
{
  vtkPVDataInformation* data = representation->getInputDataInformation();
  vtkPVArrayInformation* range =
    data ? data->GetFieldDataInformation()->GetArrayInformation(shapesplines::names::TorsionColorRange) : nullptr;
  if (range == nullptr)
  {
    return std::nullopt;
  }
  return range->GetComponentRange(0)[1];
}
}

//-----------------------------------------------------------------------------
pqShapeSplinesTorsionColors::pqShapeSplinesTorsionColors(QObject* parent)
  : Superclass(parent)
{
}

//-----------------------------------------------------------------------------
pqShapeSplinesTorsionColors::~pqShapeSplinesTorsionColors() = default;

//-----------------------------------------------------------------------------
void pqShapeSplinesTorsionColors::onStartup()
{
  pqServerManagerModel* model = pqApplicationCore::instance()->getServerManagerModel();
  QObject::connect(
    model, &pqServerManagerModel::representationAdded, this, &pqShapeSplinesTorsionColors::watch);
  // The plugin can be loaded after representations exist (Tools > Manage Plugins).
  for (pqDataRepresentation* representation : model->findItems<pqDataRepresentation*>())
  {
    this->watch(representation);
  }
}

//-----------------------------------------------------------------------------
void pqShapeSplinesTorsionColors::onShutdown() {}

//-----------------------------------------------------------------------------
void pqShapeSplinesTorsionColors::watch(pqRepresentation* representation)
{
  auto* data = qobject_cast<pqDataRepresentation*>(representation);
  if (data == nullptr)
  {
    return;
  }
  // New data (Apply, a time step), another colour array, another map (Separate
  // Color Map): each can leave the map over the data's range.
  const auto changed = [this, data]() { this->schedule(data); };
  QObject::connect(data, &pqDataRepresentation::dataUpdated, this, changed);
  QObject::connect(data, &pqDataRepresentation::colorArrayNameModified, this, changed);
  QObject::connect(data, &pqDataRepresentation::colorTransferFunctionModified, this, changed);
}

//-----------------------------------------------------------------------------
void pqShapeSplinesTorsionColors::schedule(pqDataRepresentation* representation)
{
  // The signals come in the middle of an Apply or an update, before ParaView
  // rescales the maps to the data; the rescale here runs once the event loop
  // is back, after them, and once for a burst of signals.
  if (this->Changed.isEmpty())
  {
    QTimer::singleShot(0, this, &pqShapeSplinesTorsionColors::rescaleScheduled);
  }
  if (!this->Changed.contains(representation))
  {
    this->Changed.push_back(representation);
  }
}

//-----------------------------------------------------------------------------
void pqShapeSplinesTorsionColors::rescaleScheduled()
{
  QSet<vtkSMProxy*> maps;
  for (const auto& representation : this->Changed)
  {
    if (representation && ColorsByTorsion(representation))
    {
      if (vtkSMProxy* map = representation->getLookupTableProxy())
      {
        maps.insert(map);
      }
    }
  }
  this->Changed.clear();

  const QList<pqDataRepresentation*> representations =
    pqApplicationCore::instance()->getServerManagerModel()->findItems<pqDataRepresentation*>();
  for (vtkSMProxy* map : maps)
  {
    if (vtkSMPropertyHelper(map, "AutomaticRescaleRangeMode", /*quiet=*/true).GetAsInt() ==
        vtkSMTransferFunctionManager::NEVER)
    {
      continue; // the user's range
    }
    // A map is shared by every representation coloured by Torsion: one range
    // for all the visible ones, as ParaView's own rescale does.
    double m = 0.0;
    bool measured = true;
    QList<pqDataRepresentation*> users;
    for (pqDataRepresentation* representation : representations)
    {
      if (representation->getLookupTableProxy() == map && representation->isVisible() &&
          ColorsByTorsion(representation))
      {
        const std::optional<double> robust = RobustTorsion(representation);
        measured = measured && robust.has_value();
        m = std::max(m, robust.value_or(0.0));
        users.push_back(representation);
      }
    }
    double range[2];
    if (!measured || m <= 0.0 ||
        (vtkSMTransferFunctionProxy::GetRange(map, range) && range[0] == -m && range[1] == m))
    {
      continue;
    }
    vtkSMTransferFunctionProxy::RescaleTransferFunction(map, -m, m);
    if (vtkSMProxy* opacity =
          vtkSMPropertyHelper(map, "ScalarOpacityFunction", /*quiet=*/true).GetAsProxy())
    {
      vtkSMTransferFunctionProxy::RescaleTransferFunction(opacity, -m, m);
    }
    for (pqDataRepresentation* user : users)
    {
      user->renderViewEventually();
    }
  }
}
