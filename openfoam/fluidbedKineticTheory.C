#include "fluidbedKineticTheory.H"
#include "fluidbedLawParameters.H"
#include "fluidbedFieldParts.H"
#include "addToRunTimeSelectionTable.H"
#include "fvcGrad.H"

namespace Foam
{
namespace kineticTheoryModels
{
namespace radialModels
{
    defineTypeNameAndDebug(fluidbedRadial, 0);
    addToRunTimeSelectionTable(radialModel, fluidbedRadial, dictionary);
}
namespace granularPressureModels
{
    defineTypeNameAndDebug(fluidbedGranularPressure, 0);
    addToRunTimeSelectionTable
    (
        granularPressureModel,
        fluidbedGranularPressure,
        dictionary
    );
}
namespace viscosityModels
{
    defineTypeNameAndDebug(fluidbedViscosity, 0);
    addToRunTimeSelectionTable(viscosityModel, fluidbedViscosity, dictionary);
}
namespace conductivityModels
{
    defineTypeNameAndDebug(fluidbedConductivity, 0);
    addToRunTimeSelectionTable
    (
        conductivityModel,
        fluidbedConductivity,
        dictionary
    );
}
namespace frictionalStressModels
{
    defineTypeNameAndDebug(fluidbedFrictionalStress, 0);
    addToRunTimeSelectionTable
    (
        frictionalStressModel,
        fluidbedFrictionalStress,
        dictionary
    );
}
}
}


namespace
{

using namespace Foam;
using namespace Foam::fluidbedFieldParts;

// The solids fraction the laws take: a negative round-off of the
// transported fraction is 0.
tmp<volScalarField> solidFraction(const volScalarField& alpha)
{
    return max(alpha, scalar(0));
}

// The rate-of-strain invariants the frictional laws take: tr D and D':D'.
tmp<volScalarField> divergence(const volSymmTensorField& D)
{
    return tr(D);
}

tmp<volScalarField> contraction(const volSymmTensorField& D)
{
    return dev(D) && dev(D);
}

// The bridge of a transport coefficient (nu, kappa): a law of
// (phi, Theta, g0, d, rho_s, e).
typedef size_t (*TransportBridge)
(
    const fluidbed_kt_law*, size_t, const double*, const double*,
    const double*, const double*, const double*, double, double*, char*,
    size_t
);

// A transport coefficient evaluated by `bridge` over every part of the mesh.
tmp<volScalarField> transportCoefficient
(
    const kineticTheoryModels::fluidbedLaw& law,
    const TransportBridge bridge,
    const word& name,
    const dimensionSet& dimensions,
    const volScalarField& alpha1,
    const volScalarField& Theta,
    const volScalarField& g0,
    const volScalarField& rho1,
    const volScalarField& da,
    const dimensionedScalar& e
)
{
    const fvMesh& mesh = alpha1.mesh();
    const tmp<volScalarField> tphi(solidFraction(alpha1));
    tmp<volScalarField> tresult(newField(name, mesh, dimensions));
    forEachPart(mesh, [&](const label part)
    {
        char message[1024];
        const label n = partSize(mesh, part);
        law.check
        (
            bridge
            (
                law.get(), n, in(tphi(), part), in(Theta, part),
                in(g0, part), in(da, part), in(rho1, part), e.value(),
                out(tresult.ref(), part), message, sizeof message
            ),
            n, message
        );
    });
    return tresult;
}

} // End anonymous namespace


// * * * * * * * * * * * * * * * * fluidbedLaw  * * * * * * * * * * * * * * //

Foam::kineticTheoryModels::fluidbedLaw::fluidbedLaw
(
    const dictionary& dict,
    fluidbed_kt_kind kind,
    const wordList& ownKeys
)
{
    const word name(dict.get<word>("law"));
    char message[1024];
    law_.reset(fluidbed_kt_law_create(kind, name.c_str(), message, sizeof message));
    if (!law_)
    {
        FatalIOErrorInFunction(dict) << message << exit(FatalIOError);
    }
    setFluidbedLawParameters(dict, ownKeys, law_.get(), fluidbed_kt_law_set);
    Info<< "fluidbed kinetic-theory law " << this->name() << endl;
}


void Foam::kineticTheoryModels::fluidbedLaw::check
(
    size_t evaluated,
    label n,
    const char* message
) const
{
    if (evaluated != static_cast<size_t>(n))
    {
        FatalErrorInFunction
            << "fluidbed law " << name() << ", element " << evaluated
            << ": " << message << exit(FatalError);
    }
}


// * * * * * * * * * * * * * * * fluidbedComparison * * * * * * * * * * * * //

Foam::kineticTheoryModels::fluidbedComparison::fluidbedComparison
(
    const dictionary& compareDict
)
:
    minAlpha_(compareDict.getOrDefault<scalar>("minAlpha", 0)),
    maxAlpha_(compareDict.getOrDefault<scalar>("maxAlpha", 1))
{}


void Foam::kineticTheoryModels::fluidbedComparison::report
(
    const word& quantity,
    const char* law,
    const word& against,
    const volScalarField& alpha,
    const volScalarField& ours,
    const volScalarField& theirs
) const
{
    scalar maxRelative = 0;
    label compared = 0;
    forAll(ours, celli)
    {
        if (alpha[celli] >= minAlpha_ && alpha[celli] <= maxAlpha_)
        {
            const scalar a = ours[celli], b = theirs[celli];
            const scalar scale = max(mag(a), mag(b));
            // A NaN of either side is reported as such.
            const scalar relative =
                (a == b) ? scalar(0) : mag(a - b)/scale;
            maxRelative = (relative > maxRelative || relative != relative)
              ? relative : maxRelative;
            ++compared;
        }
    }
    reduce(maxRelative, maxOp<scalar>());
    reduce(compared, sumOp<label>());
    Info<< "fluidbed: " << quantity << " of " << law << " against "
        << against << ": max relative difference " << maxRelative
        << " over " << compared << " cells with " << minAlpha_
        << " <= alpha <= " << maxAlpha_ << endl;
}


// * * * * * * * * * * * * * * * * * radial * * * * * * * * * * * * * * * * //

Foam::kineticTheoryModels::radialModels::fluidbedRadial::fluidbedRadial
(
    const dictionary& dict
)
:
    radialModel(dict),
    law_
    (
        dict.subDict("fluidbedRadialCoeffs"),
        FLUIDBED_KT_RADIAL_DISTRIBUTION,
        wordList(1, word("slopeFloor"))
    ),
    slopeFloor_
    (
        dict.subDict("fluidbedRadialCoeffs").getOrDefault<scalar>
        (
            "slopeFloor", 1e-6
        )
    ),
    reference_(dict.subDict("fluidbedRadialCoeffs"))
{}


Foam::tmp<Foam::volScalarField>
Foam::kineticTheoryModels::radialModels::fluidbedRadial::evaluate
(
    const volScalarField& alpha,
    const dimensionedScalar& alphaMinFriction,
    const dimensionedScalar& alphaMax,
    bool slope
) const
{
    const fvMesh& mesh = alpha.mesh();
    const tmp<volScalarField> tphi(solidFraction(alpha));
    tmp<volScalarField> tg0(newField("g0", mesh, dimless));
    tmp<volScalarField> tg0prime(newField("g0prime", mesh, dimless));
    forEachPart(mesh, [&](const label part)
    {
        char message[1024];
        const label n = partSize(mesh, part);
        law_.check
        (
            fluidbed_kt_radial_distribution
            (
                law_.get(), alphaMax.value(), alphaMinFriction.value(),
                slopeFloor_, n, in(tphi(), part), out(tg0.ref(), part),
                slope ? out(tg0prime.ref(), part) : nullptr,
                message, sizeof message
            ),
            n, message
        );
    });
    return slope ? tg0prime : tg0;
}


Foam::tmp<Foam::volScalarField>
Foam::kineticTheoryModels::radialModels::fluidbedRadial::g0
(
    const volScalarField& alpha,
    const dimensionedScalar& alphaMinFriction,
    const dimensionedScalar& alphaMax
) const
{
    tmp<volScalarField> tg0(evaluate(alpha, alphaMinFriction, alphaMax, false));
    reference_.compare
    (
        "g0", law_.name(), alpha, tg0(),
        [&](const radialModel& theirs)
        {
            return theirs.g0(alpha, alphaMinFriction, alphaMax);
        }
    );
    return tg0;
}


Foam::tmp<Foam::volScalarField>
Foam::kineticTheoryModels::radialModels::fluidbedRadial::g0prime
(
    const volScalarField& alpha,
    const dimensionedScalar& alphaMinFriction,
    const dimensionedScalar& alphaMax
) const
{
    tmp<volScalarField> tg0prime
    (
        evaluate(alpha, alphaMinFriction, alphaMax, true)
    );
    reference_.compare
    (
        "g0prime", law_.name(), alpha, tg0prime(),
        [&](const radialModel& theirs)
        {
            return theirs.g0prime(alpha, alphaMinFriction, alphaMax);
        }
    );
    return tg0prime;
}


// * * * * * * * * * * * * * * * granular pressure * * * * * * * * * * * * * //

Foam::kineticTheoryModels::granularPressureModels::fluidbedGranularPressure::
fluidbedGranularPressure(const dictionary& dict)
:
    granularPressureModel(dict),
    law_
    (
        dict.subDict("fluidbedGranularPressureCoeffs"),
        FLUIDBED_KT_GRANULAR_PRESSURE
    ),
    reference_(dict.subDict("fluidbedGranularPressureCoeffs"))
{}


Foam::tmp<Foam::volScalarField>
Foam::kineticTheoryModels::granularPressureModels::fluidbedGranularPressure::
evaluate
(
    const volScalarField& alpha1,
    const volScalarField& g0,
    const volScalarField* g0prime,
    const volScalarField& rho1,
    const dimensionedScalar& e
) const
{
    const fvMesh& mesh = alpha1.mesh();
    const tmp<volScalarField> tphi(solidFraction(alpha1));
    tmp<volScalarField> tcoeff
    (
        newField("granularPressureCoeff", mesh, rho1.dimensions())
    );
    tmp<volScalarField> tslope
    (
        newField("granularPressureCoeffPrime", mesh, rho1.dimensions())
    );
    forEachPart(mesh, [&](const label part)
    {
        char message[1024];
        const label n = partSize(mesh, part);
        law_.check
        (
            fluidbed_kt_granular_pressure
            (
                law_.get(), n, in(tphi(), part), in(g0, part),
                g0prime ? in(*g0prime, part) : nullptr, in(rho1, part),
                e.value(), out(tcoeff.ref(), part),
                g0prime ? out(tslope.ref(), part) : nullptr,
                message, sizeof message
            ),
            n, message
        );
    });
    return g0prime ? tslope : tcoeff;
}


Foam::tmp<Foam::volScalarField>
Foam::kineticTheoryModels::granularPressureModels::fluidbedGranularPressure::
granularPressureCoeff
(
    const volScalarField& alpha1,
    const volScalarField& g0,
    const volScalarField& rho1,
    const dimensionedScalar& e
) const
{
    tmp<volScalarField> tcoeff(evaluate(alpha1, g0, nullptr, rho1, e));
    reference_.compare
    (
        "granularPressureCoeff", law_.name(), alpha1, tcoeff(),
        [&](const granularPressureModel& theirs)
        {
            return theirs.granularPressureCoeff(alpha1, g0, rho1, e);
        }
    );
    return tcoeff;
}


Foam::tmp<Foam::volScalarField>
Foam::kineticTheoryModels::granularPressureModels::fluidbedGranularPressure::
granularPressureCoeffPrime
(
    const volScalarField& alpha1,
    const volScalarField& g0,
    const volScalarField& g0prime,
    const volScalarField& rho1,
    const dimensionedScalar& e
) const
{
    tmp<volScalarField> tslope(evaluate(alpha1, g0, &g0prime, rho1, e));
    reference_.compare
    (
        "granularPressureCoeffPrime", law_.name(), alpha1, tslope(),
        [&](const granularPressureModel& theirs)
        {
            return theirs.granularPressureCoeffPrime
            (
                alpha1, g0, g0prime, rho1, e
            );
        }
    );
    return tslope;
}


// * * * * * * * * * * * * * * * * viscosity * * * * * * * * * * * * * * * //

Foam::kineticTheoryModels::viscosityModels::fluidbedViscosity::
fluidbedViscosity(const dictionary& dict)
:
    viscosityModel(dict),
    law_(dict.subDict("fluidbedViscosityCoeffs"), FLUIDBED_KT_SHEAR_VISCOSITY),
    reference_(dict.subDict("fluidbedViscosityCoeffs"))
{}


Foam::tmp<Foam::volScalarField>
Foam::kineticTheoryModels::viscosityModels::fluidbedViscosity::nu
(
    const volScalarField& alpha1,
    const volScalarField& Theta,
    const volScalarField& g0,
    const volScalarField& rho1,
    const volScalarField& da,
    const dimensionedScalar& e
) const
{
    tmp<volScalarField> tnu
    (
        transportCoefficient
        (
            law_, fluidbed_kt_shear_viscosity, "nu", dimViscosity,
            alpha1, Theta, g0, rho1, da, e
        )
    );
    reference_.compare
    (
        "nu", law_.name(), alpha1, tnu(),
        [&](const viscosityModel& theirs)
        {
            return theirs.nu(alpha1, Theta, g0, rho1, da, e);
        }
    );
    return tnu;
}


// * * * * * * * * * * * * * * * * conductivity  * * * * * * * * * * * * * * //

Foam::kineticTheoryModels::conductivityModels::fluidbedConductivity::
fluidbedConductivity(const dictionary& dict)
:
    conductivityModel(dict),
    law_(dict.subDict("fluidbedConductivityCoeffs"), FLUIDBED_KT_CONDUCTIVITY),
    reference_(dict.subDict("fluidbedConductivityCoeffs"))
{}


Foam::tmp<Foam::volScalarField>
Foam::kineticTheoryModels::conductivityModels::fluidbedConductivity::kappa
(
    const volScalarField& alpha1,
    const volScalarField& Theta,
    const volScalarField& g0,
    const volScalarField& rho1,
    const volScalarField& da,
    const dimensionedScalar& e
) const
{
    tmp<volScalarField> tkappa
    (
        transportCoefficient
        (
            law_, fluidbed_kt_conductivity, "kappa",
            dimensionSet(1, -1, -1, 0, 0), alpha1, Theta, g0, rho1, da, e
        )
    );
    reference_.compare
    (
        "kappa", law_.name(), alpha1, tkappa(),
        [&](const conductivityModel& theirs)
        {
            return theirs.kappa(alpha1, Theta, g0, rho1, da, e);
        }
    );
    return tkappa;
}


// * * * * * * * * * * * * * * * frictional stress * * * * * * * * * * * * * //

Foam::kineticTheoryModels::frictionalStressModels::fluidbedFrictionalStress::
fluidbedFrictionalStress(const dictionary& dict)
:
    frictionalStressModel(dict),
    reference_(dict.subDict("fluidbedFrictionalStressCoeffs"))
{
    const dictionary& coeffs = dict.subDict("fluidbedFrictionalStressCoeffs");
    if (coeffs.found("law"))
    {
        stress_.reset(new fluidbedLaw(coeffs, FLUIDBED_KT_FRICTIONAL_STRESS));
    }
    else
    {
        pressure_.reset
        (
            new fluidbedLaw
            (
                coeffs.subDict("pressure"), FLUIDBED_KT_FRICTIONAL_PRESSURE
            )
        );
        if (coeffs.found("viscosity"))
        {
            viscosity_.reset
            (
                new fluidbedLaw
                (
                    coeffs.subDict("viscosity"),
                    FLUIDBED_KT_FRICTIONAL_VISCOSITY
                )
            );
        }
        else
        {
            Info<< "fluidbed: no frictional viscosity law: nuFric is 0"
                << endl;
        }
    }
}


const char*
Foam::kineticTheoryModels::frictionalStressModels::fluidbedFrictionalStress::
pressureName() const
{
    return stress_.valid() ? stress_->name() : pressure_->name();
}


Foam::tmp<Foam::volScalarField>
Foam::kineticTheoryModels::frictionalStressModels::fluidbedFrictionalStress::
stress
(
    const phaseModel& phase,
    const dimensionedScalar& alphaMinFriction,
    const dimensionedScalar& alphaMax,
    const volSymmTensorField& D,
    int which
) const
{
    const fvMesh& mesh = phase.mesh();
    const tmp<volScalarField> tphi(solidFraction(phase));
    const volScalarField& Theta = mesh.lookupObject<volScalarField>
    (
        IOobject::groupName("Theta", phase.name())
    );
    const tmp<volScalarField> td(phase.d());
    const tmp<volScalarField> tdivergence(divergence(D));
    const tmp<volScalarField> tcontraction(contraction(D));
    tmp<volScalarField> tpressure(newField("pf", mesh, dimPressure));
    tmp<volScalarField> tslope(newField("pfPrime", mesh, dimPressure));
    tmp<volScalarField> tmu(newField("muFric", mesh, dimDynamicViscosity));
    forEachPart(mesh, [&](const label part)
    {
        char message[1024];
        const label n = partSize(mesh, part);
        stress_->check
        (
            fluidbed_kt_frictional_stress
            (
                stress_->get(), alphaMax.value(), alphaMinFriction.value(),
                n, in(tphi(), part), in(Theta, part), in(td(), part),
                in(tdivergence(), part), in(tcontraction(), part),
                out(tpressure.ref(), part), out(tslope.ref(), part),
                out(tmu.ref(), part), message, sizeof message
            ),
            n, message
        );
    });
    return which == 0 ? tpressure : which == 1 ? tslope : tmu;
}


Foam::tmp<Foam::volScalarField>
Foam::kineticTheoryModels::frictionalStressModels::fluidbedFrictionalStress::
pressure
(
    const phaseModel& phase,
    const dimensionedScalar& alphaMinFriction,
    const dimensionedScalar& alphaMax,
    bool slope
) const
{
    const fvMesh& mesh = phase.mesh();
    if (stress_.valid())
    {
        const volSymmTensorField D(symm(fvc::grad(phase.U())));
        return stress(phase, alphaMinFriction, alphaMax, D, slope ? 1 : 0);
    }
    const tmp<volScalarField> tphi(solidFraction(phase));
    tmp<volScalarField> tpressure(newField("pf", mesh, dimPressure));
    tmp<volScalarField> tslope(newField("pfPrime", mesh, dimPressure));
    forEachPart(mesh, [&](const label part)
    {
        char message[1024];
        const label n = partSize(mesh, part);
        pressure_->check
        (
            fluidbed_kt_frictional_pressure
            (
                pressure_->get(), alphaMax.value(), alphaMinFriction.value(),
                n, in(tphi(), part), out(tpressure.ref(), part),
                slope ? out(tslope.ref(), part) : nullptr,
                message, sizeof message
            ),
            n, message
        );
    });
    return slope ? tslope : tpressure;
}


Foam::tmp<Foam::volScalarField>
Foam::kineticTheoryModels::frictionalStressModels::fluidbedFrictionalStress::
frictionalPressure
(
    const phaseModel& phase,
    const dimensionedScalar& alphaMinFriction,
    const dimensionedScalar& alphaMax
) const
{
    tmp<volScalarField> tpf(pressure(phase, alphaMinFriction, alphaMax, false));
    reference_.compare
    (
        "frictionalPressure", pressureName(), phase, tpf(),
        [&](const frictionalStressModel& theirs)
        {
            return theirs.frictionalPressure(phase, alphaMinFriction, alphaMax);
        }
    );
    return tpf;
}


Foam::tmp<Foam::volScalarField>
Foam::kineticTheoryModels::frictionalStressModels::fluidbedFrictionalStress::
frictionalPressurePrime
(
    const phaseModel& phase,
    const dimensionedScalar& alphaMinFriction,
    const dimensionedScalar& alphaMax
) const
{
    tmp<volScalarField> tslope(pressure(phase, alphaMinFriction, alphaMax, true));
    reference_.compare
    (
        "frictionalPressurePrime", pressureName(), phase, tslope(),
        [&](const frictionalStressModel& theirs)
        {
            return theirs.frictionalPressurePrime
            (
                phase, alphaMinFriction, alphaMax
            );
        }
    );
    return tslope;
}


Foam::tmp<Foam::volScalarField>
Foam::kineticTheoryModels::frictionalStressModels::fluidbedFrictionalStress::nu
(
    const phaseModel& phase,
    const dimensionedScalar& alphaMinFriction,
    const dimensionedScalar& alphaMax,
    const volScalarField& pf,
    const volSymmTensorField& D
) const
{
    const fvMesh& mesh = phase.mesh();
    const volScalarField& rho = phase.rho();
    tmp<volScalarField> tmu;
    if (stress_.valid())
    {
        tmu = stress(phase, alphaMinFriction, alphaMax, D, 2);
    }
    else
    {
        tmu = newField("muFric", mesh, dimDynamicViscosity);
        if (viscosity_.valid())
        {
            // The solver passes p_f/rho_s.
            const tmp<volScalarField> tpressure(pf*rho);
            const tmp<volScalarField> tdivergence(divergence(D));
            const tmp<volScalarField> tcontraction(contraction(D));
            forEachPart(mesh, [&](const label part)
            {
                char message[1024];
                const label n = partSize(mesh, part);
                viscosity_->check
                (
                    fluidbed_kt_frictional_viscosity
                    (
                        viscosity_->get(), n, in(tpressure(), part),
                        in(tdivergence(), part), in(tcontraction(), part),
                        out(tmu.ref(), part), message, sizeof message
                    ),
                    n, message
                );
            });
        }
    }
    tmp<volScalarField> tnu(tmu/rho);
    reference_.compare
    (
        "nuFric",
        stress_.valid() ? stress_->name()
      : viscosity_.valid() ? viscosity_->name() : "no viscosity law",
        phase,
        tnu(),
        [&](const frictionalStressModel& theirs)
        {
            return theirs.nu(phase, alphaMinFriction, alphaMax, pf, D);
        }
    );
    return tnu;
}
