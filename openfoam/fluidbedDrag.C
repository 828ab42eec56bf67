#include "fluidbedDrag.H"
#include "fluidbedLawParameters.H"
#include "fluidbedFieldParts.H"
#include "phasePair.H"
#include "addToRunTimeSelectionTable.H"

#include <cmath>

namespace Foam
{
namespace dragModels
{
    defineTypeNameAndDebug(fluidbedDrag, 0);
    addToRunTimeSelectionTable(dragModel, fluidbedDrag, dictionary);
}
}


Foam::dragModels::fluidbedDrag::fluidbedDrag
(
    const dictionary& dict,
    const phasePair& pair,
    const bool registerObject
)
:
    dragModel(pair, registerObject),
    report_(dict.lookupOrDefault<Switch>("report", false)),
    minParticleFraction_(dict.lookupOrDefault<scalar>("minParticleFraction", 0)),
    compareMinAlpha_(pair.dispersed().residualAlpha().value()),
    checkedTimeIndex_(-1)
{
    const word name(dict.get<word>("law"));
    char message[1024];
    law_.reset(fluidbed_drag_law_create(name.c_str(), message, sizeof message));
    if (!law_)
    {
        FatalIOErrorInFunction(dict)
            << message << exit(FatalIOError);
    }
    if (!(minParticleFraction_ >= 0 && minParticleFraction_ < 1))
    {
        FatalIOErrorInFunction(dict)
            << "minParticleFraction " << minParticleFraction_
            << " is not in [0, 1)" << exit(FatalIOError);
    }
    setFluidbedLawParameters
    (
        dict,
        wordList({"type", "report", "minParticleFraction"}),
        law_.get(),
        fluidbed_drag_law_set
    );
    Info<< "fluidbed drag law " << fluidbed_drag_law_name(law_.get())
        << " for " << pair.name() << endl;

    if (dict.found("compareWith"))
    {
        const dictionary& compareDict = dict.subDict("compareWith");
        const word type(compareDict.get<word>("type"));
        compareDict.readIfPresent("minAlpha", compareMinAlpha_);
        auto cstrIter = dictionaryConstructorTablePtr_->cfind(type);
        if (!cstrIter.found())
        {
            FatalIOErrorInLookup
            (
                compareDict, "dragModel", type, *dictionaryConstructorTablePtr_
            ) << exit(FatalIOError);
        }
        // Not registered: the solver's registry holds this model under the
        // name that both would take.
        reference_.reset(cstrIter()(compareDict, pair, false).ptr());
    }
}


void Foam::dragModels::fluidbedDrag::check(const volScalarField& K) const
{
    const label timeIndex = K.mesh().time().timeIndex();
    if (timeIndex == checkedTimeIndex_)
    {
        return;
    }
    checkedTimeIndex_ = timeIndex;

    const scalarField& alpha = pair_.dispersed().primitiveField();
    if (report_)
    {
        const tmp<volScalarField> tslip(pair_.magUr());
        const scalarField& slip = tslip().primitiveField();
        label notFinite = 0;
        label zeroSlip = 0;
        label empty = 0;
        forAll(K, celli)
        {
            notFinite += !std::isfinite(K[celli]);
            zeroSlip += slip[celli] == 0;
            empty += alpha[celli] <= 0;
        }
        reduce(notFinite, sumOp<label>());
        reduce(zeroSlip, sumOp<label>());
        reduce(empty, sumOp<label>());
        Info<< "fluidbed: K of " << fluidbed_drag_law_name(law_.get())
            << " over " << returnReduce(K.size(), sumOp<label>())
            << " cells: " << notFinite << " not finite, " << zeroSlip
            << " at zero slip, " << empty << " without particles, range "
            << gMin(K.primitiveField()) << " to " << gMax(K.primitiveField())
            << endl;
    }
    if (!reference_.valid())
    {
        return;
    }

    const tmp<volScalarField> tKref(reference_->K());
    const scalarField& Kref = tKref().primitiveField();
    // fluidbed's Reynolds number, rho alpha_c |Ur| d/mu (the one at which
    // OpenFOAM's GidaspowSchillerNaumann switches to its Newton branch)
    const tmp<volScalarField> tRe(pair_.continuous()*pair_.Re());
    const scalarField& Re = tRe().primitiveField();
    scalar maxRelative = 0;
    scalar maxRe = 0;
    label compared = 0;
    forAll(Kref, celli)
    {
        if (alpha[celli] >= compareMinAlpha_)
        {
            maxRelative = max
            (
                maxRelative,
                mag(K[celli] - Kref[celli])/mag(Kref[celli])
            );
            maxRe = max(maxRe, Re[celli]);
            ++compared;
        }
    }
    reduce(maxRelative, maxOp<scalar>());
    reduce(maxRe, maxOp<scalar>());
    const label excluded =
        returnReduce(Kref.size() - compared, sumOp<label>());
    reduce(compared, sumOp<label>());
    Info<< "fluidbed: K of " << fluidbed_drag_law_name(law_.get())
        << " against " << reference_->type() << ": max relative difference "
        << maxRelative << " over " << compared << " cells with alpha >= "
        << compareMinAlpha_ << " (" << excluded << " excluded), max Re "
        << maxRe << endl;
}


void Foam::dragModels::fluidbedDrag::evaluate
(
    label n,
    const scalar* phi,
    const scalar* slip,
    const scalar* rho,
    const scalar* mu,
    const scalar* d,
    scalar* beta
) const
{
    char message[1024];
    const size_t size = static_cast<size_t>(n);
    const size_t bad = fluidbed_drag_law_pressure_gradient_beta
    (
        law_.get(), size, phi, slip, rho, mu, d, beta,
        message, sizeof message
    );
    if (bad != size)
    {
        FatalErrorInFunction
            << "fluidbed law " << fluidbed_drag_law_name(law_.get())
            << " for " << pair_.name() << ", element " << bad << ": "
            << message << exit(FatalError);
    }
}


Foam::tmp<Foam::volScalarField> Foam::dragModels::fluidbedDrag::beta
(
    const scalar minPhi
) const
{
    const fvMesh& mesh = pair_.phase1().mesh();

    volScalarField phi("fluidbed:phi", pair_.dispersed());
    phi.max(dimensionedScalar("minPhi", dimless, minPhi));
    const tmp<volScalarField> tslip(pair_.magUr());
    const volScalarField& rho = pair_.continuous().rho();
    const tmp<volScalarField> tmu(pair_.continuous().mu());
    const tmp<volScalarField> td(pair_.dispersed().d());

    using namespace fluidbedFieldParts;
    tmp<volScalarField> tbeta
    (
        newField(IOobject::groupName("beta", pair_.name()), mesh, dimK)
    );
    forEachPart(mesh, [&](const label part)
    {
        evaluate
        (
            partSize(mesh, part),
            in(phi, part),
            in(tslip(), part),
            in(rho, part),
            in(tmu(), part),
            in(td(), part),
            out(tbeta.ref(), part)
        );
    });

    return tbeta;
}


Foam::tmp<Foam::volScalarField> Foam::dragModels::fluidbedDrag::K() const
{
    tmp<volScalarField> tK(beta(minParticleFraction_));
    if (report_ || reference_.valid())
    {
        check(tK());
    }
    return tK;
}


Foam::tmp<Foam::volScalarField> Foam::dragModels::fluidbedDrag::Ki() const
{
    // Ki is K per particle fraction; where there are (almost) no particles
    // its limit is taken at the dispersed fraction residualAlpha, so that the
    // face coefficient Kf (interpolated Ki times the face fraction) keeps the
    // finite per-particle drag of those cells instead of 0.
    const scalar residualAlpha = pair_.dispersed().residualAlpha().value();
    return
        beta(max(residualAlpha, minParticleFraction_))
       /max(pair_.dispersed(), pair_.dispersed().residualAlpha());
}


Foam::tmp<Foam::volScalarField> Foam::dragModels::fluidbedDrag::CdRe() const
{
    return
        Ki()*sqr(pair_.dispersed().d())
       /(0.75*pair_.continuous().rho()*pair_.continuous().nu());
}
