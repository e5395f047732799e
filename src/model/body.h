#pragma once
/// \file body.h
/// A rigid (or soft) body: what the user defined, its state, and the mass properties and
/// geometry derived from them.

#include "model/color.h"
#include "model/constants.h"
#include "model/scalar.h"
#include "model/shape.h"

#include <compare>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace impetus::model {

/// A strong index into World::bodies. Springs and joints refer to bodies by id, never by pointer,
/// so a World copies with `=`.
struct BodyId {
    std::uint32_t index = 0; ///< position in World::bodies
    auto operator<=>(const BodyId&) const = default; ///< memberwise order
};

/// Surface material. Mixing two materials in a contact is the contact solver's business.
struct Material {
    Scalar restitution = 0.5; ///< coefficient of restitution e, 0 (plastic) … 1 (elastic)
    Scalar friction = 0.5; ///< Coulomb friction coefficient μ ≥ 0 (0.5: wood on wood)
    bool operator==(const Material&) const = default; ///< memberwise equality
};

/// Whether the user gave the body's areal density or its total mass. The other follows from the
/// area. Kept so that the editor and a saved file show what the user chose.
enum class MassMode { Density, Mass };

/// The user's mass choice: `value` is a density in kg/m² (MassMode::Density) or a mass in kg.
struct MassSpec {
    MassMode mode = MassMode::Density; ///< what `value` is
    Scalar value = 1.0; ///< kg/m² or kg, > 0
    bool operator==(const MassSpec&) const = default; ///< memberwise equality
};

/// How a soft body's grid-spring damping is given (scene keys `dampingRatio` and `damping`).
enum class SoftDampingMode {
    /// A damping ratio ζ, dimensionless: every grid spring gets c = 2ζ·√(k·m_eff), with m_eff the
    /// reduced mass of the two ellipses it joins (docs/physics.md, "Soft mode").
    Ratio,
    /// A damping coefficient c in N·s/m, the same for every grid spring.
    Coefficient,
};

/// Soft-mode settings (scene key `soft`). The body is then simulated as a grid of small ellipses
/// joined by springs; see docs/physics.md.
struct SoftSettings {
    bool autoDensity = false; ///< true: pick ellipsesPerSquareMeter from this machine's speed
    Scalar ellipsesPerSquareMeter = 64; ///< grid density n, 1/m² (cell side 1/√n); typical 64–1024
    Scalar stiffness = 2000; ///< spring constant of the grid springs, N/m
    /// Which of dampingRatio and damping applies; the other is kept but not used.
    SoftDampingMode dampingMode = SoftDampingMode::Ratio;
    /// Damping ratio ζ of the grid springs, dimensionless (1 = critical for a pair of ellipses);
    /// used when dampingMode is Ratio. The default lands a soft box nearly dead (docs/physics.md).
    Scalar dampingRatio = constants::kDefaultSoftDampingRatio;
    /// Damping of the grid springs along their length, N·s/m; used when dampingMode is Coefficient.
    Scalar damping = 1.0;
    bool operator==(const SoftSettings&) const = default; ///< memberwise equality
};

/// The state of a soft body's grid as a scene file keeps it (scene key `soft.state`, an addition to
/// the contract): where every ellipse is and how it moves, in the order the grid numbers them
/// (row by row from the bottom left of the lattice).
struct SoftGridState {
    std::vector<Vec2> positions; ///< ellipse centres, world, m
    std::vector<Vec2> velocities; ///< m/s, one per position
    bool operator==(const SoftGridState&) const = default; ///< memberwise equality
};

/// The kinematic state of a body.
struct BodyState {
    Vec2 position = Vec2::Zero(); ///< world position of the centre of mass, m
    Scalar angle = 0; ///< rad, counter-clockwise
    Vec2 velocity = Vec2::Zero(); ///< velocity of the centre of mass, m/s
    Scalar angularVelocity = 0; ///< rad/s, counter-clockwise
    bool operator==(const BodyState&) const = default; ///< memberwise equality
};

/// Geometry derived from the shape, in the body frame whose origin is the centre of mass.
struct BodyGeometry {
    /// Where the body-frame origin (the centroid) lies in the user's shape frame: the polygon's
    /// centroid, or zero for the symmetric shapes. Local point = user point − centroidOffset.
    Vec2 centroidOffset = Vec2::Zero();
    /// Outline of a box or polygon, counter-clockwise, in the body frame. Empty for round shapes.
    std::vector<Vec2> outline;
    /// Convex pieces of a box or polygon (one piece when convex), counter-clockwise, body frame.
    std::vector<std::vector<Vec2>> convexPieces;
    /// Outward unit normal of each edge of each convex piece: pieceNormals[k][i] belongs to the
    /// edge from convexPieces[k][i] to convexPieces[k][i+1].
    std::vector<std::vector<Vec2>> pieceNormals;
    /// Radius of the smallest origin-centred circle that holds the shape, m.
    Scalar boundingRadius = 0;
    bool operator==(const BodyGeometry&) const = default; ///< memberwise equality
};

/// A body. The fields up to `soft` are the user's definition; call updateDerived() after changing
/// `shape`, `massSpec` or `fixed` so that the derived fields below follow.
struct Body {
    std::string name; ///< unique within the world, non-empty
    Shape shape = Circle{}; ///< the body's own shape (scene key `shape`), body frame
    BodyState state; ///< position, angle and velocities now
    MassSpec massSpec; ///< density or mass, as the user gave it
    Material material; ///< restitution and friction
    /// A fixed body has infinite mass and feels no force: it moves only with the velocity and
    /// angular velocity it is given (zero by default: it stays put), like a conveyor belt or a
    /// turning drum, whatever hits it.
    bool fixed = false;
    Color color; ///< fill colour in the app (scene key `color`)
    std::optional<SoftSettings> soft; ///< present: soft mode
    /// A soft body's grid state read from a file saved mid-run. controller::prepareSoftBodies puts
    /// the grid there when it first builds it (if the counts match) and then clears this; a file
    /// written later takes the state from the grid itself. Empty for a body read without one.
    std::optional<SoftGridState> softState;

    // Derived by updateDerived().
    Scalar area = 0; ///< m²
    Scalar mass = 0; ///< kg, from the geometry (reported even for fixed bodies)
    Scalar inertia = 0; ///< moment of inertia about the centre of mass, kg·m²
    Scalar invMass = 0; ///< 1/mass, or 0 for a fixed body, 1/kg
    Scalar invInertia = 0; ///< 1/inertia, or 0 for a fixed body, 1/(kg·m²)
    BodyGeometry geometry; ///< outline, convex pieces and bounds in the body frame

    // Collision state, kept up to date by the simulation; not part of the scene file.
    bool colliding = false; ///< in contact with another body at the end of the last step
    std::int64_t collisionCount = 0; ///< contact-begin events this body has taken part in

    bool operator==(const Body&) const = default; ///< memberwise equality

    /// Recomputes area, mass, inertia, their inverses and the geometry from shape, massSpec and
    /// fixed. Precondition: the shape is valid (positive sizes, a simple polygon).
    void updateDerived();

    /// Areal density, kg/m², whichever way the mass was given.
    Scalar density() const;

    /// A body-frame point (m) in world coordinates: position + R(angle)·local.
    Vec2 worldPoint(const Vec2& local) const;

    /// The world velocity (m/s) of the body's material point at world position `world`: v + ω × r.
    Vec2 velocityAt(const Vec2& world) const;
};

} // namespace impetus::model
