#include "fluidbedDrag.H"
#include "phasePair.H"
#include "addToRunTimeSelectionTable.H"

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
    compareMinAlpha_(1e-4),
    comparedTimeIndex_(-1)
{
    const word name(dict.get<word>("law"));
    char message[1024];
    law_.reset(fluidbed_drag_law_create(name.c_str(), message, sizeof message));
    if (!law_)
    {
        FatalIOErrorInFunction(dict)
            << message << exit(FatalIOError);
    }
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


void Foam::dragModels::fluidbedDrag::compare(const volScalarField& K) const
{
    const label timeIndex = K.mesh().time().timeIndex();
    if (timeIndex == comparedTimeIndex_)
    {
        return;
    }
    comparedTimeIndex_ = timeIndex;

    const tmp<volScalarField> tKref(reference_->K());
    const scalarField& Kref = tKref().primitiveField();
    const scalarField& alpha = pair_.dispersed().primitiveField();
    scalar maxRelative = 0;
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
            ++compared;
        }
    }
    reduce(maxRelative, maxOp<scalar>());
    reduce(compared, sumOp<label>());
    Info<< "fluidbed: K of " << fluidbed_drag_law_name(law_.get())
        << " against " << reference_->type() << ": max relative difference "
        << maxRelative << " over " << compared << " cells with alpha >= "
        << compareMinAlpha_ << endl;
}


void Foam::dragModels::fluidbedDrag::evaluate
(
    label n,
    const scalar* voidage,
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
        law_.get(), size, voidage, slip, rho, mu, d, beta,
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
    const scalar maxVoidage
) const
{
    const fvMesh& mesh = pair_.phase1().mesh();

    volScalarField voidage("fluidbed:voidage", pair_.continuous());
    voidage.min(dimensionedScalar("maxVoidage", dimless, maxVoidage));
    const tmp<volScalarField> tslip(pair_.magUr());
    const volScalarField& rho = pair_.continuous().rho();
    const tmp<volScalarField> tmu(pair_.continuous().mu());
    const tmp<volScalarField> td(pair_.dispersed().d());

    tmp<volScalarField> tbeta
    (
        new volScalarField
        (
            IOobject
            (
                IOobject::groupName("fluidbed:beta", pair_.name()),
                mesh.time().timeName(),
                mesh,
                IOobject::NO_READ,
                IOobject::NO_WRITE,
                false
            ),
            mesh,
            dimensionedScalar(dimK, Zero)
        )
    );
    volScalarField& beta = tbeta.ref();

    evaluate
    (
        mesh.nCells(),
        voidage.primitiveField().cdata(),
        tslip().primitiveField().cdata(),
        rho.primitiveField().cdata(),
        tmu().primitiveField().cdata(),
        td().primitiveField().cdata(),
        beta.primitiveFieldRef().data()
    );

    volScalarField::Boundary& betab = beta.boundaryFieldRef();
    forAll(betab, patchi)
    {
        evaluate
        (
            betab[patchi].size(),
            voidage.boundaryField()[patchi].cdata(),
            tslip().boundaryField()[patchi].cdata(),
            rho.boundaryField()[patchi].cdata(),
            tmu().boundaryField()[patchi].cdata(),
            td().boundaryField()[patchi].cdata(),
            betab[patchi].data()
        );
    }

    return tbeta;
}


Foam::tmp<Foam::volScalarField> Foam::dragModels::fluidbedDrag::K() const
{
    tmp<volScalarField> tK(beta(1));
    if (reference_.valid())
    {
        compare(tK());
    }
    return tK;
}


Foam::tmp<Foam::volScalarField> Foam::dragModels::fluidbedDrag::Ki() const
{
    // Ki is K per particle fraction; where there are (almost) no particles
    // its limit is taken at the dispersed fraction residualAlpha, so that the
    // face coefficient Kf (interpolated Ki times the face fraction) keeps the
    // finite per-particle drag of those cells instead of 0.
    const scalar residual = pair_.dispersed().residualAlpha().value();
    return
        beta(1 - residual)
       /max(pair_.dispersed(), pair_.dispersed().residualAlpha());
}


Foam::tmp<Foam::volScalarField> Foam::dragModels::fluidbedDrag::CdRe() const
{
    return
        Ki()*sqr(pair_.dispersed().d())
       /(0.75*pair_.continuous().rho()*pair_.continuous().nu());
}
