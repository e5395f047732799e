#pragma once
/// \file view_constants.h
/// Every tuning constant of the desktop view, with its unit and the reason for its value.
/// Nothing here is physical: these only decide how often the view runs the engine and how the
/// canvas looks.

#include <QColor>

#include <cstddef>
#include <cstdint>

namespace impetus::view::constants {

/// Interval of the run timer, ms. 16 ms is about one 60 Hz display frame; the runner measures the
/// real elapsed time anyway, so a late tick only means more fixed steps in the next batch.
inline constexpr int kFrameIntervalMs = 16;

/// The most simulated time one batch of steps may catch up, s. When a frame takes longer than this
/// (a slow machine, a debugger pause, a dragged window, a step that is slow to compute) the rest
/// of the wall time is dropped: simulated time runs slower instead of the runner ever taking a
/// larger step or piling up a backlog it could never work off (the "spiral of death").
inline constexpr double kMaxSimulatedTimePerFrame = 0.1;

/// The most wall time one batch of steps computes before it is shown, ms. The steps run on a
/// worker thread, so this does not keep the window responsive (it always is); it keeps the canvas
/// showing a new state about once per 16 ms frame when the steps cannot keep up, rather than
/// only after a whole kMaxSimulatedTimePerFrame of them. A batch that runs out drops the rest of
/// its backlog: simulated time slows down, the step never changes.
inline constexpr double kMaxBatchWallTimeMs = 12.0;

/// How long Step (→) waits for its step before leaving it to the background, ms. 100 ms is the
/// limit under which a response feels immediate, so a step that fast is shown at once, as if it
/// were taken on the spot; a slower one is shown when it ends, and meanwhile the window keeps
/// painting and answering.
inline constexpr int kStepWaitMs = 100;

/// Hardware threads that the GUI thread and the step worker's thread take, one each: the engine's
/// second thread (SolverSettings::secondThread) is used only on a machine with more than this.
inline constexpr unsigned kCoresForGuiAndWorker = 2;

/// The runner measures how a run keeps up with the wall clock over windows of this much running
/// wall time, s: long enough to hold several frames and batches, short enough for the window to
/// say within a second that the simulation runs slower than real time.
inline constexpr double kPaceWindowSeconds = 1.0;

/// The speed shown is averaged over this many windows, so that a step which lands in one window
/// but not the next does not make the figure jump from second to second.
inline constexpr std::size_t kPaceWindowsAveraged = 3;

/// A window that drops more than this fraction of the simulated time it owed runs slower than
/// real time. 5 %: a single hitch of the event loop (a window dragged for a moment) is not
/// reported; a run whose steps cannot keep up drops far more.
inline constexpr double kBehindTolerance = 0.05;

/// The time steps the attribute pane accepts, s. Below 10 µs a classroom scene needs more than
/// 100 000 steps per simulated second, so it crawls; above 0.1 s (10 Hz) contacts and springs are
/// resolved too coarsely to mean anything. A scene file may hold any positive step.
inline constexpr double kMinEditableTimeStep = 1e-5;
inline constexpr double kMaxEditableTimeStep = 0.1;
/// A spring's page offers a time step this share of the longest its integrator holds the spring
/// at (model::longestStableSpringStep), to three significant digits, down.
inline constexpr double kStableStepShare = 0.95;

/// Space left around the bodies when a scene is framed, as a fraction of the larger side of their
/// bounding box, on each side. 8 % keeps outlines off the window edge without wasting the canvas.
inline constexpr double kFrameMarginFraction = 0.08;

/// The smallest margin around framed bodies, m, so that a single small body is not blown up to fill
/// the whole window.
inline constexpr double kMinimumFrameMargin = 0.5;

/// The smallest region a scene is framed to, m. A lone 5 cm ball is shown in a 2 m window, which
/// is what a student expects from "a small ball", rather than magnified fifty times.
inline constexpr double kMinimumFrameExtent = 2.0;

/// Region framed when a world has no bodies at all, m (width, height), centred on the origin.
inline constexpr double kEmptyWorldWidth = 10.0;
inline constexpr double kEmptyWorldHeight = 6.0;

/// How far the scene rectangle reaches beyond the framed region, as a multiple of its size. The
/// scroll bars are hidden, but QGraphicsView only centres on points inside its scene rectangle;
/// this leaves room for bodies that fly away and for the later pan and zoom tools.
inline constexpr double kSceneRectPaddingFactor = 50.0;

/// The grid spacing grows through 1, 2, 5 × 10ⁿ m until neighbouring lines are at least this far
/// apart on screen, px: dense enough to read distances, sparse enough to stay in the background.
inline constexpr double kMinimumGridSpacingPx = 28.0;

/// Width of body outlines and springs, px (cosmetic: the same at every zoom).
inline constexpr double kOutlineWidthPx = 1.5;
/// The canvas's cached layer of paper, grid and trails (canvas_view.h) takes in the trails' growth
/// and is painted whole once no new state has come for this long while not running, ms: at rest
/// the canvas shows exactly what a whole paint shows, a few frames after the last step.
inline constexpr int kLayerSettleMs = 100;
/// Distance between the diagonal lines of a fixed or colliding body's hatch, px along a row: that
/// of Qt's 8 × 8 pattern brushes, which the hatch stood for (polygon_painting.h).
inline constexpr double kHatchSpacingPx = 8.0;
/// Widest outline drawn edge by edge as square-capped lines (polygon_painting.h): at 2 px their
/// corners stick out past a round join by 0.41 px at most. Wider (projector mode's thick lines),
/// the outline is stroked with its round joins.
inline constexpr double kEdgeLinesMaxWidthPx = 2.0;

/// A round body's stamped picture (body_stamps.h) puts its centre on a grid of this many steps
/// per pixel: within 1/8 px of the true centre, which antialiasing cannot show, with 16 pictures
/// per look and size.
inline constexpr int kStampSubpixelSteps = 4;
/// The most stamp pictures kept (about 4 KB each at a 12 px radius); beyond it they are all
/// dropped and drawn again as needed, which only a long series of zooms reaches.
inline constexpr std::size_t kMaxBodyStamps = 2048;

/// Outline colour factor for QColor::darker(): 160 % darker than the fill reads as an edge.
inline constexpr int kOutlineDarkerFactor = 160;

/// Fill of a fixed body relative to its colour (QColor::darker()), and its hatch colour.
inline constexpr int kFixedFillDarkerFactor = 125;
inline constexpr int kFixedHatchDarkerFactor = 200;

/// Colour of a colliding body, fill and outline base (contract: colliding bodies are red whatever
/// their own colour). #dc2626: a clear red that stays red on a washed-out projector.
inline constexpr int kCollidingRed = 0xdc;
inline constexpr int kCollidingGreen = 0x26;
inline constexpr int kCollidingBlue = 0x26;

/// A soft body's details (docs/app.md, "Soft bodies"). Grid springs are coloured by strain
/// L/L₀ − 1 from blue (compressed) through grey (rest) to red (stretched), saturating at ±10 %:
/// a visible squash is a few per cent, and a tenth is already a hard crush.
inline constexpr double kStrainColourFullScale = 0.10;
inline constexpr int kStrainRestGrey = 0x90; ///< grey of a spring at rest length
inline constexpr int kSoftEllipseGrey = 0x40; ///< outline of a soft body's ellipses
inline constexpr double kSoftSpringWidthPx = 1.0; ///< px, cosmetic
inline constexpr double kSoftEllipseWidthPx = 0.75; ///< px, cosmetic
/// Z value of the soft-detail items: above bodies (z 0) and springs, below tool overlays.
inline constexpr double kSoftDetailZ = 5.0;

/// Simulation › Compare Soft with Rigid runs this long, s, and lists about this many samples: a
/// few seconds show a landing and its rebound, and twenty rows fit a dialog.
inline constexpr double kCompareRigidSeconds = 3.0;
inline constexpr std::int64_t kCompareRigidRows = 20;

/// Number of zig-zag corners drawn on a spring. Fixed, so a stretched spring shows longer teeth.
inline constexpr int kSpringZigZagCorners = 12;

/// Half-width of a spring's zig-zag, m: visible at classroom scales (metres) but narrower than a
/// typical body.
inline constexpr double kSpringHalfWidth = 0.07;

/// The spring's zig-zag is at most this fraction of its rest length wide, so short springs stay
/// springs and do not turn into wide triangles.
inline constexpr double kSpringMaxHalfWidthPerLength = 0.15;

/// Straight lead at each end of a spring, as a fraction of its current length.
inline constexpr double kSpringLeadFraction = 0.1;

/// Radius of the marker drawn at a spring's fixed world anchor, px.
inline constexpr double kAnchorMarkerRadiusPx = 4.0;

/// Size of the main window on its first start, px, before QSettings holds the size the user
/// left it at: fits a 1366x768 laptop screen with its panels.
inline constexpr int kDefaultWindowWidth = 1200;
inline constexpr int kDefaultWindowHeight = 720;

/// Most commands the undo stack keeps. A run keeps two copies of the world, so a long session with
/// a large scene must not keep every one; 200 is far more undo than a lesson needs.
inline constexpr int kUndoLimit = 200;

/// Each notch of the mouse wheel zooms by this factor (toward the cursor): 1.2 takes about a dozen
/// notches to go from a whole classroom scene to a single body, without jumps that lose the place.
inline constexpr double kZoomPerWheelNotch = 1.2;

/// Limits of the zoom, px per metre: from 0.01 px/m (a 100 km field on a screen) to 10⁶ px/m
/// (a micrometre a pixel), far beyond any classroom scene either way, before the scroll bars'
/// integer range or floating point would show.
inline constexpr double kMinPixelsPerMetre = 0.01;
inline constexpr double kMaxPixelsPerMetre = 1e6;

/// Grid labels: the point size of their font, their distance from the edge and the line, px.
inline constexpr double kGridLabelPointSize = 7.5;
inline constexpr double kGridLabelPaddingPx = 3.0;

/// How near the cursor must be to a spring or joint to pick it, px: a thin line needs a margin a
/// hand can hit.
inline constexpr double kPickTolerancePx = 6.0;

/// Polygon tool: a click this close to the first vertex closes the polygon, px.
inline constexpr double kCloseToFirstVertexPx = 8.0;

/// Drag tools: a drag shorter than this is a click and draws nothing, px (a shaky click is not a
/// 1 mm box).
inline constexpr double kMinimumDragPx = 4.0;

/// Arrow keys move the selection by this many grid spacings (Shift: kNudgeLargeFactor times more),
/// so a nudge is the same on screen at every zoom.
inline constexpr double kNudgeGridFraction = 0.1;
inline constexpr double kNudgeLargeFactor = 10.0;

/// Rotate tool: with Shift held the angle snaps to multiples of this, degrees.
inline constexpr double kRotationSnapDegrees = 15.0;

/// Radius of a pin joint's marker, px.
inline constexpr double kPinMarkerRadiusPx = 5.0;

/// Width of a rod joint's line, px.
inline constexpr double kRodWidthPx = 3.0;

/// Radius of the dot in a pin's ring, as a fraction of the ring's radius.
inline constexpr double kPinDotFraction = 0.4;

/// Opacity of the fill of a shape being drawn and of the rubber band: enough to see the area, light
/// enough to see the bodies under it.
inline constexpr double kPreviewFillAlpha = 0.12;
inline constexpr double kRubberBandFillAlpha = 0.08;

/// Width of the selection outline drawn over selected items, px.
inline constexpr double kSelectionWidthPx = 2.5;

/// Canvas colours: a near-white paper, light grey grid lines, and slightly darker axes.
inline const QColor kBackgroundColor{0xfa, 0xfa, 0xf9};
inline const QColor kMinorGridColor{0xe7, 0xe5, 0xe4};
inline const QColor kMajorGridColor{0xd6, 0xd3, 0xd1};
inline const QColor kAxisColor{0xa8, 0xa2, 0x9e};
inline const QColor kSpringColor{0x44, 0x40, 0x3c};
/// Joints (pins and rods): a dark slate, apart from the springs' warm grey.
inline const QColor kJointColor{0x33, 0x41, 0x55};
/// Grid labels: the axis grey, dark enough to read on the paper.
inline const QColor kGridLabelColor{0x78, 0x71, 0x6c};
/// The selection outline, and the tools' drawing previews: an amber that no body colour or the
/// collision red is confused with.
inline const QColor kSelectionColor{0xf5, 0x9e, 0x0b};
inline const QColor kPreviewColor{0x25, 0x63, 0xeb};

// ---- Instruments (issue 13) ----

/// The timeline keeps the world every this many fixed steps (a keyframe) and replays the steps in
/// between when the user goes back to one: 240 steps is 1 s at the default step, so going back
/// replays at most a second of simulation (microseconds for a classroom scene), and a 5-minute run
/// of the 2000-body scene keeps 300 keyframes (docs/app.md, "Timeline").
inline constexpr std::int64_t kKeyframeIntervalSteps = 240;

/// The most memory the timeline's keyframes may take, bytes. When one more would pass it, every
/// other periodic keyframe is dropped and the interval doubles, so a run of any length fits.
/// 256 MiB (268 MB) leaves room under the 500 MB a 5-minute run of the 2000-body scene may use
/// in the window with its arrows, trails (kMaxTrailPointsInAll) and a graph on: the rest of the
/// window took about 200 MB there (bench/timeline_memory.cpp, docs/app.md "Timeline").
inline constexpr std::size_t kTimelineMemoryBudgetBytes = std::size_t{256} * 1024 * 1024;

/// The timeline slider's steps are fixed steps; its page (a click in the groove) moves this many.
inline constexpr int kTimelinePageSteps = 240;

/// Vector arrows: the scale of the legend, "1 unit = this many metres on the canvas", that a new
/// canvas starts with for each kind, and the factor one click of the legend's − and + changes it by.
inline constexpr double kDefaultVelocityScale = 0.25; ///< m of arrow per m/s
inline constexpr double kDefaultAccelerationScale = 0.05; ///< m of arrow per m/s²
inline constexpr double kDefaultForceScale = 0.05; ///< m of arrow per N
inline constexpr double kDefaultMomentumScale = 0.25; ///< m of arrow per kg·m/s
inline constexpr double kVectorScaleStep = 2.0;

/// Arrows shorter than this on screen are not drawn, px: a head on a zero-length shaft is noise.
inline constexpr double kMinArrowPx = 2.0;
/// Arrow shaft width and head length, px: constant on screen, so arrows read at every zoom.
inline constexpr double kArrowWidthPx = 2.5;
inline constexpr double kArrowHeadPx = 9.0;
/// The longest arrow drawn, px: a huge impact force is clipped to this (and drawn dashed) rather
/// than crossing the whole window.
inline constexpr double kMaxArrowPx = 2000.0;

/// Arrow colours, one per quantity, told apart from each other and from body colours.
inline const QColor kVelocityColor{0x16, 0xa3, 0x4a};
inline const QColor kAccelerationColor{0xc0, 0x26, 0xd3};
inline const QColor kNetForceColor{0xdc, 0x26, 0x26};
inline const QColor kGravityColor{0x7c, 0x3a, 0xed};
inline const QColor kSpringForceColor{0x92, 0x40, 0x0e};
inline const QColor kDragForceColor{0x0e, 0x74, 0x90};
inline const QColor kContactNormalColor{0x1d, 0x4e, 0xd8};
inline const QColor kFrictionColor{0xea, 0x58, 0x0c};
inline const QColor kJointForceColor{0x47, 0x55, 0x69};
inline const QColor kMomentumColor{0x0f, 0x76, 0x6e};

/// The legend's box in the canvas's top-left corner: margin and padding, px.
inline constexpr double kLegendMarginPx = 8.0;
inline constexpr double kLegendPaddingPx = 6.0;

/// Trails: a dot every this many steps by default (24 steps is 0.1 s at the default step: ten
/// dots a second, far enough apart to see their spacing change).
inline constexpr int kDefaultTrailDotSteps = 24;
/// The most points a trail keeps per body: 36 000 steps is 2.5 minutes at the default step; the
/// oldest go first.
inline constexpr std::size_t kMaxTrailPoints = 36000;
/// The most points all trails keep together, so that trails on a large scene stay small: 4 million
/// points of 24 bytes (about 100 MB). The 2000-body scene keeps 2000 per body, 8 s at 240 Hz.
inline constexpr std::size_t kMaxTrailPointsInAll = 4000000;
/// The canvas draws trails into a cached layer and adds only their new points while running; a
/// trail's dropped oldest points stay in that layer until it is painted whole again, which
/// happens once some trail has dropped this fraction of its greatest length: a whole repaint of
/// the 2000 trails of the 2000-body scene costs many frames' budget, so it is done every
/// quarter of a trail's length (2 s of that run) rather than every frame, and the trails shown
/// run at most a quarter longer than kept in between.
inline constexpr double kTrailTrimRedrawFraction = 0.25;
/// Trail line width and dot radius, px. One pixel keeps the trail on Qt's fast path for thin lines:
/// at 1.5 px the 2000 trails of the 2000-body scene took 1.3 s a paint after 6 s, at 1 px 0.2 s
/// (bench/frame_budget.cpp).
inline constexpr double kTrailWidthPx = 1.0;
inline constexpr double kTrailDotRadiusPx = 2.5;
/// Trail colour alpha: the path reads under the bodies without hiding them.
inline constexpr int kTrailAlpha = 170;
/// A traced point's path (the Trace Point tool): one colour for every traced point, apart from
/// the bodies' own trail colours and the arrows', one pixel wide as a trail (Qt's fast path), drawn
/// over the bodies; a ring of this radius marks the point itself, px.
inline const QColor kTracedPointColor{0xdb, 0x27, 0x77};
inline constexpr double kTracedPointWidthPx = 1.0;
inline constexpr double kTracedPointRingPx = 4.0;
/// A click within this distance of a traced point on the Trace Point tool stops tracing it, px.
inline constexpr double kTracedPointPickPx = 8.0;

/// Graphs: the samples one graph keeps at least (1 h at the default step); the oldest go first,
/// an eighth of this at a time (kGraphTrimShare).
inline constexpr std::size_t kMaxGraphSamples = 864000;
/// A graph drops its oldest samples once it holds this share of kMaxGraphSamples more, all at once
/// (7.5 min of samples at the default step): dropping the few of each frame from the front of an
/// hour's samples moved the whole hour in memory (about 170 MB) at every frame.
inline constexpr double kGraphTrimShare = 0.125;
/// A graph redraws its series at most this often while running, ms: Qt Charts redraws a series
/// of thousands of points slower than the physics adds them.
inline constexpr int kGraphRefreshMs = 100;

/// Energy ledger chart: the most points it keeps; beyond that every other one is dropped, so a
/// long run stays readable and cheap to redraw (a stacked area redraws all its points).
inline constexpr std::size_t kMaxLedgerPoints = 2000;
/// Fill alpha of the ledger chart's bands: the band edges stay visible where bands cross zero.
inline constexpr int kLedgerBandAlpha = 200;

/// Ruler and protractor: how close to a body centre or vertex a click snaps to it, px.
inline constexpr double kMeasureSnapPx = 10.0;
inline const QColor kMeasureColor{0x0f, 0x17, 0x2a};

/// How often the open scene is autosaved, ms (view/autosave.h): a minute, so that a crash loses at
/// most a minute of work, while writing a classroom scene (a few kB) that often costs nothing.
inline constexpr int kAutosaveIntervalMs = 60 * 1000;

} // namespace impetus::view::constants
