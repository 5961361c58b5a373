/**
 * @class pqShapeSplinesTorsionColors
 * @brief Centres the Torsion colour map on zero, over the spline filters' robust range.
 *
 * ParaView colours a spline filter's output by Torsion (its active scalars)
 * over the data's range; on noisy polylines a few spikes of torsion stretch
 * that range so far that the whole curve looks pale. Each spline output
 * carries field data TorsionColorRange = (-m, m), m the 95th percentile of
 * |torsion|. This auto-start watches the GUI's representations and, whenever
 * one coloured by the point array Torsion has its data updated or its colouring
 * changed, rescales its colour map and opacity function to [-m, m], m the
 * largest among the visible representations that share the map.
 *
 * It leaves a map alone when the user locked its range (AutomaticRescaleRangeMode
 * "Never", which Rescale to Custom Range sets), or when one of the representations
 * sharing it has no TorsionColorRange (Torsion from elsewhere, whose range it cannot
 * judge). It acts once control is back in the event loop, that is after an Apply has
 * finished: pqApplyBehavior's last step grows every unlocked map to the data range.
 */
#ifndef pqShapeSplinesTorsionColors_h
#define pqShapeSplinesTorsionColors_h

#include <QList>
#include <QObject>
#include <QPointer>

class pqDataRepresentation;
class pqRepresentation;

class pqShapeSplinesTorsionColors : public QObject
{
  Q_OBJECT
  typedef QObject Superclass;

public:
  pqShapeSplinesTorsionColors(QObject* parent = nullptr);
  ~pqShapeSplinesTorsionColors() override;

  /**
   * Watches the representations that exist and those to come.
   */
  void onStartup();

  /**
   * Nothing to undo: the connections end with this object.
   */
  void onShutdown();

private:
  Q_DISABLE_COPY(pqShapeSplinesTorsionColors)

  void watch(pqRepresentation* representation);
  void schedule(pqDataRepresentation* representation);
  void rescaleScheduled();

  // Representations changed since the last rescale; gone ones become null.
  QList<QPointer<pqDataRepresentation>> Changed;
};

#endif
